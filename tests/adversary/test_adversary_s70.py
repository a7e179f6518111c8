"""Stop 70: the review's findings (tests/adversary/s70/review).  See tests/adversary/README.md, Stop 70.  The
pytest plugin's and the dask path's are replayed in tests/test_pytest_plugin_collect.py and
tests/test_distributed.py."""
import json
import re

from adversary_cli import cli


def _twin(catalog_claim) -> str:
    """A claims file whose claim copies every declared field of a catalog claim (its id, labels, statement, sizes,
    erratum sizes, erratum and place), with a true body of its own."""
    c = catalog_claim
    return (
        "from stiefelsym import admissible, claim\n\n\n"
        f"@claim({c.id!r}, paper={tuple(c.paper)!r}, kind={c.kind!r}, section={c.section!r}, sizes=admissible(n_max=5),\n"
        f"       fails_at=lambda n, r: n >= 2, place={c.place!r},\n"
        f"       erratum={c.erratum!r},\n"
        f"       statement={c.statement!r})\n"
        "def twin(s):\n"
        f"    {c.title!r}\n"
        "    return {'XtX - I': s.X.T @ s.X - s.Ir}\n")


def test_a_claims_files_twin_of_a_catalog_claim_is_not_rendered_as_the_catalogs(tmp_path, catalog):
    """Finding 3: a claims file's run of a twin of manakov-dual-lax (every declared field copied, a true body), its
    meta and reruns edited into a catalog run's, was rendered as the catalog's Theorem 4.4 holding at (3,2), where it
    fails.  `report` now binds every catalog record to the installed catalog's graph at its size."""
    (tmp_path / "twin.py").write_text(_twin(catalog.get("manakov-dual-lax")))
    out = tmp_path / "run"
    run = cli("verify", "--claims", str(tmp_path / "twin.py"), "--method", "modular", "--size", "3,2",
              "--jobs", "1", "--report-dir", str(out))
    assert run.returncode == 1, run.stdout[-2000:] + run.stderr[-2000:]      # the twin holds: unexpected
    data = json.loads((out / "results.json").read_text())
    meta = data["meta"]
    meta["command"] = re.sub(r" --claims \S+", "", meta["command"])
    meta["claims_file"], meta["claims_files"] = None, []
    for r in data["results"]:
        r["rerun"] = re.sub(r" --claims \S+", "", r["rerun"])
    (out / "results.json").write_text(json.dumps(data, indent=1))
    # (stop 77: the twin's records say they shadow a catalog claim, which the claims loaded now deny)
    refused = cli("report", "--results", str(out / "results.json"), "--report-dir", str(tmp_path / "rendered"))
    assert refused.returncode == 2, refused.stdout[-2000:] + refused.stderr[-2000:]
    assert "with the id of a catalog claim, and the claims loaded now say otherwise" in refused.stderr
    for r in data["results"]:
        assert r.pop("shadows") is True
    (out / "results.json").write_text(json.dumps(data, indent=1))
    refused = cli("report", "--results", str(out / "results.json"), "--report-dir", str(tmp_path / "rendered"))
    assert refused.returncode == 2, refused.stdout[-2000:] + refused.stderr[-2000:]
    assert "whose graph is not their catalog claim's" in refused.stderr
    assert not (tmp_path / "rendered" / "verification.md").exists()
