"""The Python API on a user's claims file, as the second user trial of stop 62 used it: the rerun command of a
result names the file (as the command line's does), sizes may be given as "n,r" texts, a file that cannot be loaded
raises the exported CatalogError, and a run that names a claim traces only that claim at the run's sizes (a size of
200 asked for one claim traced the file's other claims there first: 185 s before the budget refused the run)."""
from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

import stiefelsym

CLAIMS = '''
from stiefelsym import admissible, claim


@claim("api-true", kind="id", sizes=admissible(n_max=3))
def true_one(s):
    """XᵀX = I."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}


@claim("api-false", kind="id", sizes=admissible(n_max=3))
def false_one(s):
    """XᵀP = 0 (false)."""
    return {"XtP": s.X.T @ s.P}


@claim("api-other", kind="id", sizes=admissible(n_max=3))
def other(s):
    """Another claim of the file: it says where it is traced (a size read through the door, printed to stderr)."""
    print("api-other traced at n =", int(s.n))
    return {"XtX - I": s.X.T @ s.X - s.Ir}
'''


@pytest.fixture()
def claims_file(tmp_path):
    f = tmp_path / "api_claims.py"
    f.write_text(textwrap.dedent(CLAIMS))
    return f


def test_the_rerun_command_of_a_result_names_the_file_and_runs(claims_file, tmp_path):
    res = stiefelsym.verify("api-false", files=claims_file, sizes=["3,2"], methods="exact")
    assert res[0].verdict == "fails" and f"--claims {claims_file}" in res[0].rerun, res[0].rerun
    argv = res[0].rerun.split()
    assert argv[:2] == ["stiefelsym", "verify"]
    run = subprocess.run([sys.executable, "-m", "stiefelsym", *argv[1:], "--no-report"], capture_output=True,
                         text=True, timeout=300, cwd=str(tmp_path))
    assert run.returncode == 1 and "api-false (3,2) exact: fails" in run.stdout, run.stdout + run.stderr


def test_sizes_as_texts_and_bad_sizes(claims_file):
    res = stiefelsym.verify("api-true", files=claims_file, sizes=["3,2", (2, 1)], methods="modular")
    assert [(r.n, r.r, r.verdict) for r in res] == [(3, 2, "checked"), (2, 1, "checked")]
    with pytest.raises(ValueError, match="is not a size"):
        stiefelsym.verify("api-true", files=claims_file, sizes=["3;2"])


def test_a_missing_file_raises_the_exported_catalog_error(tmp_path):
    with pytest.raises(stiefelsym.CatalogError, match="claims file not found"):
        stiefelsym.verify(files=tmp_path / "nope.py")


def test_only_the_named_claims_are_traced_at_the_runs_sizes(claims_file, capfd):
    from stiefelsym.run.userfile import load_claims_isolated
    load_claims_isolated(claims_file, [(50, 25)], only=["api-true"])
    assert "api-other traced at n = 50" not in capfd.readouterr().err
    load_claims_isolated(claims_file, [(50, 25)])        # the control: unnamed, it is traced there
    assert "api-other traced at n = 50" in capfd.readouterr().err
