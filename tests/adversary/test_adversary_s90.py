"""Stop 90's replays: a sweep of the API surfaces less attacked before (h2) and the paper's statements written afresh
as a user's claims files (h1), their tricks kept as tests.

h2 (the in-process Python API, the pytest plugin, corrections, discover and mutate on a user's file, check, the
Jupyter reprs) found three wrong verdicts, closed here:
- W1: a correction appended, in the caller's process, to a catalog claim (``claim.correction(...)(f)``, the public
  decorator) was taken for one the catalog registered, so the claim's reviewed reason of equivariance reduced the
  user's function to X = X0 and exact proved "the last row of X vanishes" at (3, 2).
- W2: the same reason bought by ``dataclasses.replace(catalog_claim, func=f)`` or by a claim of one's own given
  ``reviewed=True``.  A claim is now reviewed by identity only: the catalog's loading registers each of its claims
  with the functions its reason was reviewed with (its own and the corrections registered with it), and
  ``reviewed`` is no field (no argument, copy or pickle gives it).
- W3: a file whose name starts with "_" or "conftest", named on pytest's command line (``pytest --stiefelsym
  claims/*.py``), was imported by pytest in its own process, where it replaced the plugin's items' runtest and a
  false claim passed.  A .py file named on the command line is now a claims file whatever its name (as
  ``stiefelsym verify --claims _x.py`` reads it), loaded in child processes; only conftest.py itself is left to
  pytest, as its configuration.

h1 wrote 89 claims (48 of the paper's statements in its own form, 41 false twins) in 12 files: 5,054 verdicts
under modular, float, auto, exact and free at n <= 4 against its own numpy, no wrong verdict (s90/h1/verdicts.tsv;
its numpy truth at (3, 2) in s90/h1/truth_3_2.tsv).
"""
from __future__ import annotations

import dataclasses
import pickle
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from adversary_replay import verdicts_by_size

from stiefelsym import admissible, load_catalog
from stiefelsym.claims import Claim, reviewed_functions

ROOT = Path(__file__).parents[2]
H1 = Path(__file__).parent / "s90" / "h1"
H2 = Path(__file__).parent / "s90" / "h2"


def _api(script: str, *args: str) -> list[str]:
    out = subprocess.run([sys.executable, str(H2 / script), *args], capture_output=True, text=True, timeout=600,
                         cwd=ROOT)
    assert out.returncode == 0, out.stderr[-2000:]
    return [line for line in out.stdout.splitlines() if " exact: " in line or " auto: " in line]


def bottom_row(s):
    return {"x": s.X[2:3, :]}


def test_a_claim_is_reviewed_by_the_catalog_s_loading_and_by_nothing_a_user_can_write():
    base = load_catalog().get("neum-gras")
    assert base.reviewed and base.func in reviewed_functions(base)
    assert not dataclasses.replace(base, func=bottom_row).reviewed
    assert not dataclasses.replace(base).reviewed                       # a copy is another object
    assert not pickle.loads(pickle.dumps(base)).reviewed
    with pytest.raises(TypeError):
        dataclasses.replace(base, reviewed=True)
    with pytest.raises(TypeError):
        Claim(id="mine", paper=("p",), kind="id", section="t", func=bottom_row, sizes=admissible(3),
              equivariance="the rows rotate", reviewed=True)
    with pytest.raises((AttributeError, dataclasses.FrozenInstanceError)):
        object.__setattr__(dataclasses.replace(base, func=bottom_row), "reviewed", True)


def test_a_correction_added_later_is_not_reviewed_with_the_catalog_claim():
    c = load_catalog().get("ym-monopole")
    registered = reviewed_functions(c)
    c.correction("mine: the last row of X vanishes")(bottom_row)
    assert reviewed_functions(c) == registered and bottom_row not in registered
    assert c.corrected(len(c.corrections) - 1).reviewed == (c.corrected(len(c.corrections) - 1) is c)
    assert bottom_row not in reviewed_functions(c.corrected(len(c.corrections) - 1))


def test_a_reviewed_reason_is_not_bought_in_process_by_a_correction_or_a_copy():
    # W1: the user's corrections of ym-monopole (false on T*V, true at X = X0) fail; its own correction is proved
    lines = _api("api_reviewed.py", "b", "exact,auto")
    mine = [line for line in lines if "[mine:" in line]
    assert len(mine) == 4 and all(": fails --" in line for line in mine), lines
    assert any("[the Lorentz force with the opposite sign" in line and ": proved --" in line for line in lines), lines
    # W2: the catalog claim's copy with the user's function
    lines = _api("api_reviewed.py", "a", "exact,auto")
    assert len(lines) == 2 and all(": fails --" in line for line in lines), lines


def _pytest(folder: Path, *args: str) -> subprocess.CompletedProcess:
    (folder / "pytest.ini").write_text("[pytest]\n")        # none of the repository's configuration
    return subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "--stiefelsym", *args,
                           "--stiefelsym-method", "modular", "--stiefelsym-size", "3,2", "-rA"],
                          capture_output=True, text=True, timeout=600, cwd=folder)


def test_a_file_named_on_pytest_s_command_line_is_never_imported_by_pytest(tmp_path):
    # W3: helpers named "_..." and "conftest_..." that replace the items' runtest, beside a false claim
    work = tmp_path / "pt3"
    shutil.copytree(H2 / "pt3", work)
    for rigging in ("_helpers.py", "conftest_claims.py", "_rigging_claims.py"):
        out = _pytest(work, rigging, "b_false.py")
        assert out.returncode == 1 and "FAILED b_false.py::x-dup" in out.stdout, (rigging, out.stdout[-3000:])
    # a claims file whose name starts with "_" is read when named, as `stiefelsym verify --claims` reads it
    out = _pytest(work, "_claims_underscore.py")
    assert out.returncode == 1 and "FAILED _claims_underscore.py::u-false" in out.stdout, out.stdout[-3000:]
    out = _pytest(work, "_rigging_claims.py")
    assert out.returncode == 0 and "PASSED _rigging_claims.py::rig-true" in out.stdout, out.stdout[-3000:]
    # the realistic trigger: a shell glob over a claims folder with a helper in it
    work4 = tmp_path / "pt4"
    shutil.copytree(H2 / "pt4", work4)
    out = _pytest(work4, *sorted(str(p.relative_to(work4)) for p in (work4 / "claims").glob("*.py")))
    assert out.returncode == 1 and "FAILED claims/b_false.py::x-dup" in out.stdout, out.stdout[-3000:]


H1_SAMPLE = {
    "h2_neumann.py": "modular",
    "h3_manakov.py": "auto",
    "h4_brackets.py": "exact",
}


@pytest.mark.parametrize("name,method", sorted(H1_SAMPLE.items()))
def test_h1_s_statements_and_twins_get_their_verdicts_at_3_2(name, method):
    import csv
    truth = {}
    with open(H1 / "truth_3_2.tsv", encoding="utf-8") as f:
        for row in csv.DictReader(f, delimiter="\t"):
            if row["file"] == name.removesuffix(".py"):
                truth[row["claim"]] = row["truth at (3,2)"]
    got = verdicts_by_size(H1 / name, "--method", method, "--size", "3,2")
    compared = [(cid, verdict) for (cid, n, r), verdict in got.items() if n is not None and cid in truth]
    assert len(compared) >= 4 and {truth[c] for c, _ in compared} == {"true", "false"}, (name, got)
    for cid, verdict in compared:
        if truth[cid] == "true":
            assert verdict in ("proved", "checked", "numeric"), (cid, verdict)
        else:
            assert verdict not in ("proved", "checked", "numeric"), (cid, verdict)


def test_two_claims_of_one_id_and_a_size_that_reads_twice_are_refused_in_process():
    # h2 I1: the second of two claims with one id was dropped (a false one after a true one: results.ok)
    from stiefelsym import claim, verify
    from stiefelsym.claims import Size

    def make(k):
        return lambda s: {"r": s.X.T @ s.X - k * s.Ir}
    t = claim("s90-dup", kind="id", sizes=admissible(n_max=3))(make(1)).claim
    f = dataclasses.replace(t, func=make(2))
    for order in ([t, f], [f, t]):
        with pytest.raises(ValueError, match="two different claims with the id 's90-dup'"):
            verify(order, sizes=[(3, 2)], methods=["modular"], jobs=1)

    # h2 M1: a size whose n answers differently when read again is read once, as a plain pair of ints
    reads = [0]

    class Sz(Size):
        def __getattribute__(self, k):
            if k == "n":
                reads[0] += 1
                return 3 if reads[0] <= 1 else 4
            return object.__getattribute__(self, k)
    trI4 = claim("s90-tr-in-4", kind="id", sizes=admissible(n_max=4))(lambda s: {"r": s.tr(s.In) - 4}).claim
    res = verify([trI4], sizes=[Sz(3, 2)], methods=["modular"], jobs=1)
    assert [(r.n, r.r, r.verdict) for r in res] == [(3, 2, "fails")]


def test_a_correction_s_number_of_changes_is_an_int():
    # h2 I4: changes=2.5 was accepted when registered and refused later, with the whole file, naming neither
    c = load_catalog().get("ym-monopole")
    with pytest.raises(ValueError, match="changes is the number of changes"):
        c.correction("mine", changes=2.5)


def test_two_correction_descriptions_that_read_alike_are_refused():
    # h2 I2: "use XᵀX" and "use XᵀX " were two corrections whose report lines read the same (LaTeX drops the space)
    c = load_catalog().get("ym-monopole")
    for text in ("use X^T X ", " use X^T X", "use  X^T X"):
        with pytest.raises(ValueError, match="no space at either end"):
            c.correction(text)


def test_a_record_of_a_correction_needs_its_claim_to_fail_as_printed():
    # h2 M2: `check --no-rerun` took a printed claim's `fails` edited to `checked` beside the records of its
    # corrections, which a run makes only where the claim as printed fails
    import json

    from stiefelsym.run.integrity import _missing_corrections
    data = json.loads((ROOT / "reports" / "results.json").read_text(encoding="utf-8"))
    catalog = load_catalog()
    assert _missing_corrections(data["results"], catalog, data["meta"]) == []
    for r in data["results"]:
        if r["claim"] == "ym-monopole" and r["variant"] is None and r["verdict"] == "fails":
            r["verdict"] = "checked"
    problems = _missing_corrections(data["results"], catalog, data["meta"])
    assert problems and all("a record of a run of this correction its command does not make" in p
                            for p in problems), problems


def test_a_dimension_free_result_kept_for_a_claim_s_runs_proves_only_its_own_graph():
    # the stop's own attempt on the plan's dimension-free result kept for the claim's runs at sizes (two workers
    # with the pool's affinity, auto from n = 5 on taking the kept result): a false claim beside a true one
    got = verdicts_by_size(Path(__file__).parent / "s90" / "remembered.py", "--max-n", "5", "--jobs", "2")
    sized = {k: v for k, v in got.items() if k[1] is not None}
    assert {v for (c, _, _), v in sized.items() if c == "fool-remembered-false"} == {"fails"}, got
    assert {v for (c, _, _), v in sized.items() if c == "fool-remembered-true"} == {"proved"}, got
    assert got[("fool-remembered-false", None, None)] != "proved"
