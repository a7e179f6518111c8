"""Stop 69: the review's files (tests/adversary/s69/review).  See tests/adversary/README.md, Stop 69."""
import json

from adversary_cli import HERE, cli

REVIEW = HERE / "s69" / "review"


def _report(tmp_path, *args, status=0):
    out = tmp_path / "run"
    run = cli("verify", *args, "--jobs", "1", "--report-dir", str(out))
    assert run.returncode == status, run.stdout[-2000:] + run.stderr[-2000:]
    return (out / "verification.md").read_text(), json.loads((out / "results.json").read_text())


def test_a_claims_files_erratum_is_never_counted_as_the_papers_misprint(tmp_path):
    """F1: a claims file's erratum citing the catalog's label LA3*D, with a correction in the very words of the
    catalog's, run beside double-neumann-dual-lax, was listed as "the same misprint" of the paper."""
    md, _ = _report(tmp_path, "double-neumann-dual-lax", "mine-la3d", "--claims", str(REVIEW / "merge_with_catalog.py"),
                    "--method", "modular", "--size", "2,1")
    assert "fail as printed" in md
    assert "distinct errors" not in md and "the same error" not in md


def test_two_errata_of_one_file_with_one_label_and_the_same_words_are_two(tmp_path):
    """F1: two unrelated errata of one file (one label, corrections with the same words) were counted as one
    misprint; F4: a Count's own words "(paper: 5)" were said as "printed: 5"."""
    md, _ = _report(tmp_path, "--claims", str(REVIEW / "misprint_merge.py"), "--method", "exact", "--max-n", "2")
    assert "distinct errors" not in md and "the same error" not in md
    assert "rows of X (paper: 5)" in md and "printed: 5" not in md


def test_a_claims_file_cannot_name_its_error_as_a_catalog_line(tmp_path):
    """F3: a code object given a catalog file's name, a helper in a folder named proofs/ and a message that quotes a
    catalog line were all named "(at proofs/sec3_geodesic_flows.py:N)", the catalog's form; now each error is named
    by the file its code gives, said to be the code's own naming."""
    _md, data = _report(tmp_path, "--claims", str(REVIEW / "shown_path.py"), "--method", "exact", "--size", "3,2",
                        status=1)     # three errors, which the claims do not expect
    messages = {r["claim"]: r["message"] for r in data["results"]}
    assert set(messages) == {"sp-forged-file", "sp-helper-in-proofs", "sp-message"}
    assert all(r["verdict"] == "error" for r in data["results"])
    for cid, message in messages.items():
        assert message.endswith(", as the code names its file)"), (cid, message)
        assert "(at proofs/" not in message.replace("(at proofs/sec3_geodesic_flows.py:120)", ""), (cid, message)
