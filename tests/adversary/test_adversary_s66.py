"""Stop 66: the review's files (tests/adversary/s66/review).  See tests/adversary/README.md, Stop 66."""
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

from adversary_cli import cli, HERE

REVIEW = HERE / "s66" / "review"
ENGINE = Path(__file__).resolve().parents[2] / "stiefelsym"


# -- the replay imports a step's module from a fixed list only ------------------------------------------------------

PROBE = """
import sys
from stiefelsym.ir.replay import ReplayError, _registered
try:
    _registered("stiefelsym.s66_planted.step")
    print("resolved")
except ReplayError as exc:
    print("refused", "stiefelsym.s66_planted" in sys.modules, "PLANTED" in sys.modules.get("builtins").__dict__)
"""


def test_a_module_file_planted_in_the_package_after_its_digests_is_never_imported_by_a_replay(tmp_path):
    """The replay imported, on first need, any module of the package's folder a graph named
    (stiefelsym.<file>.<step>): a file that appeared there after the package was digested (e2e_lazy_import.py:
    written by another process, and deleting itself on import) ran in the verifying worker and a false claim
    came out `checked`.  Now only the modules of the fixed list seal.STEP_MODULES are imported: a copy of the
    package with such a file planted in it refuses the name and imports nothing."""
    pkg = tmp_path / "pkg"
    shutil.copytree(ENGINE, pkg / "stiefelsym", ignore=shutil.ignore_patterns("__pycache__"))
    (pkg / "stiefelsym" / "s66_planted.py").write_text("import builtins\nbuiltins.PLANTED = True\n")
    env = dict(os.environ, PYTHONPATH=str(pkg))
    out = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=300, env=env,
                         cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["refused", "False", "False"], out.stdout


# -- a coordinate read under the dimension-free method -------------------------------------------------------------

def test_a_coordinate_read_from_real_coordinates_needs_coordinates_under_free():
    """`systems.real_coordinates(s, ["X"])[0]` under the dimension-free method raised a bare IndexError
    (`error`, exit 1) on a true claim; it needs coordinates: `undecided`, and exact proves the claim."""
    run = cli("verify", "c1u-unit-true2", "--claims", str(REVIEW / "c1_units.py"), "--method", "exact",
              "--method", "free", "--jobs", "1")
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert "free: undecided" in run.stdout and "needs coordinates" in run.stdout, run.stdout
    assert "exact: proved" in run.stdout and "IndexError" not in run.stdout


# -- report binds a record's erratum to its claim -------------------------------------------------------------------

def test_report_refuses_an_erratum_the_claim_does_not_declare(tmp_path):
    """A hand-edited results.json whose failing record was given an erratum text (and flagged expected)
    was rendered by `report` with "What is wrong: ..." for a claim that declares no erratum; `check` rejected
    it.  `report` now refuses it too, and the unedited file renders."""
    base = tmp_path / "base"
    run = cli("verify", "--claims", str(REVIEW / "c8_base.py"), "--method", "modular", "--jobs", "1",
              "--report-dir", str(base))
    assert run.returncode == 1, run.stderr[-2000:]
    ok = cli("report", "--results", str(base / "results.json"), "--report-dir", str(tmp_path / "ok"),
             "--claims", str(REVIEW / "c8_base.py"))
    assert ok.returncode == 0, ok.stderr
    data = json.loads((base / "results.json").read_text())
    for edit in ({"erratum": "a misprint of the paper: XᵀP is skew"},
                 {"erratum": "a misprint of the paper: XᵀP is skew", "expected": False}):
        forged = json.loads(json.dumps(data))
        record = next(r for r in forged["results"] if r["claim"] == "c8-false")
        record.update(edit)
        path = tmp_path / "forged.json"
        path.write_text(json.dumps(forged))
        res = cli("report", "--results", str(path), "--report-dir", str(tmp_path / "out"),
                  "--claims", str(REVIEW / "c8_base.py"))
        assert res.returncode == 2 and "refused" in res.stderr and "Traceback" not in res.stderr, res.stderr
        assert not (tmp_path / "out" / "verification.md").exists()
