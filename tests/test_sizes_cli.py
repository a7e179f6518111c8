"""Sizes on the command line: a size outside the sizes a named claim is stated for is
refused; without named claims, the claims not stated for a size skip it."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from stiefelsym.run import runner
from stiefelsym.claims import Claim, Size, SizeSpec, admissible
from stiefelsym.scene import SizeError

FILE = textwrap.dedent('''
    from stiefelsym import admissible, claim

    @claim("small", paper="t", kind="id", section="9", sizes=admissible(n_max=2, stated_n_max=2))
    def small(s):
        return {"XtX": s.X.T @ s.X - s.Ir}

    @claim("big", paper="t", kind="id", section="9",
           sizes=admissible(n_max=4, n_min=2, condition="n >= 2 (a pair of rows)", stated_n_max=4))
    def big(s):
        return {"XtX": s.X.T @ s.X - s.Ir}

    @claim("thin", paper="t", kind="id", section="9",
           sizes=admissible(n_max=4, where=lambda n, r: n >= 2 * r, condition="n >= 2r", stated_n_max=4))
    def thin(s):
        return {"XtX": s.X.T @ s.X - s.Ir}
''')


@pytest.fixture
def run(run, tmp_path):
    """The CLI in a directory holding the claims file mine.py."""
    (tmp_path / "mine.py").write_text(FILE)
    return run


def _error(result) -> str:
    assert result.exit_code == 2, (result.exit_code, result.output)
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and result.stdout == "", result.output
    return lines[0]


def test_admissible_records_the_stated_bound_and_admits_checks_it():
    spec = admissible(n_max=4, stated_n_max=4)
    assert spec.n_max == 4
    assert spec.admits(4, 2) and not spec.admits(5, 2) and not spec.admits(6, 2)
    assert max(s.n for s in spec) == 4
    default = admissible(n_max=4)                          # verified to n = 4, stated for every n
    assert max(s.n for s in default) == 4 and default.admits(9, 3) and default.n_max is None
    assert SizeSpec((Size(2, 1),)).admits(9, 3)          # no n_max: no upper bound
    assert admissible(n_max=5, stated_n_max=5).describe() == "n <= 5"
    assert admissible(4, n_min=2, r_max=2, condition="c", stated_n_max=4).describe() == "2 <= n <= 4, r <= 2 (c)"


@pytest.mark.parametrize("args, message", [
    (["small", "--size", "3,1"], "claim small is stated for sizes n <= 2; (3,1) is outside"),
    (["big", "--size", "1,1"],
     "claim big is stated for sizes 2 <= n <= 4 (n >= 2 (a pair of rows)); (1,1) is outside"),
    (["thin", "--size", "3,2"], "claim thin is stated for sizes n <= 4 (n >= 2r); (3,2) is outside"),
    (["big", "small", "--size", "2,1", "--size", "4,1"],
     "claim small is stated for sizes n <= 2; (4,1) is outside"),
    (["--size", "5,1"], "no selected claim is stated for size (5,1)"),
    (["--size", "5,1", "--size", "6,2"], "no selected claim is stated for sizes (5,1), (6,2)"),
])
def test_a_size_outside_the_stated_sizes_is_refused(run, args, message):
    line = _error(run("verify", "--claims", "mine.py", "--method", "modular", *args))
    assert line == f"stiefelsym verify: error: {message}"


def test_unnamed_claims_skip_the_sizes_they_are_not_stated_for(run):
    result = run("verify", "--claims", "mine.py", "--method", "modular", "--size", "3,1",
                 "--size", "4,2", "--format", "json")
    assert result.exit_code == 0, result.output
    got = [(r["claim"], r["n"], r["r"]) for r in json.loads(result.stdout)["results"]]
    assert got == [("big", 3, 1), ("big", 4, 2), ("thin", 3, 1), ("thin", 4, 2)]


def test_a_size_no_claim_is_stated_for_is_skipped_when_another_size_has_claims(run):
    result = run("verify", "--claims", "mine.py", "--method", "modular", "--size", "5,1", "--size", "2,1",
                 "--size", "5,1", "--format", "json")
    assert result.exit_code == 0, result.output
    got = {(r["claim"], r["n"], r["r"]) for r in json.loads(result.stdout)["results"]}
    assert got == {("big", 2, 1), ("small", 2, 1), ("thin", 2, 1)}
    assert result.stderr.count("note: (5,1): no selected claim is stated at this size; it is skipped") == 1


def test_a_named_claim_at_its_own_sizes_runs(run):
    result = run("verify", "small", "--claims", "mine.py", "--method", "modular", "--size", "2,2")
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("small (2,2) modular: checked")


def test_plan_strict_and_lenient():
    c = Claim(id="c", paper=("t",), kind="id", section="9", func=lambda s: {}, sizes=admissible(n_max=3, stated_n_max=3))
    with pytest.raises(SizeError, match=r"claim c is stated for sizes n <= 3; \(4,1\) is outside"):
        runner.plan([c], [Size(4, 1)], ["modular"], strict=True)
    with pytest.raises(SizeError, match=r"no selected claim is stated for size \(4,1\)"):
        runner.plan([c], [Size(4, 1)], ["modular"])
    assert runner.plan([c], [Size(4, 1)], ["free"], strict=True) == [(c, None, "free")]


def test_subprocess_catalog_claim_beyond_its_sizes_exits_2(tmp_path):
    """chain-algebra-commutative is stated for n >= 2 (so(1) = 0 has no invariants)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}
    proc = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "chain-algebra-commutative", "--size", "1,1",
                           "--method", "modular"], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=120, stdin=subprocess.DEVNULL)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.strip().splitlines() == [
        "stiefelsym verify: error: claim chain-algebra-commutative is stated for sizes n >= 2 "
        "(n >= 2 (so(1) = 0 has no invariants)); (1,1) is outside"]


def test_catalog_identities_are_stated_for_every_size(tmp_path):
    """The catalog verifies n <= 5 by default; an identity may be run further, e.g. n = 6."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}
    proc = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "normal-flow", "--size", "6,2",
                           "--method", "modular", "--no-report"], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=300, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("normal-flow (6,2) modular: checked")


def test_subprocess_claims_file_size_refusal(tmp_path):
    (tmp_path / "mine.py").write_text(FILE)
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}
    proc = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "small", "--claims", "mine.py",
                           "--size", "3,1"], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=120, stdin=subprocess.DEVNULL)
    assert proc.returncode == 2, proc.stderr
    assert "claim small is stated for sizes n <= 2; (3,1) is outside" in proc.stderr
    assert Path(tmp_path / "reports").exists() is False


def test_max_n_runs_every_stated_size_up_to_n_and_skips_the_rest(run):
    res = run("verify", "--claims", "mine.py", "small", "big", "thin", "--max-n", "5",
              "--no-report", "--format", "json")
    assert res.exit_code == 0, res.output
    results = json.loads(res.stdout)["results"]
    got = {(r["claim"], r["n"], r["r"]) for r in results if r["n"] is not None}
    assert {r["claim"] for r in results if r["n"] is None} == {"small", "big", "thin"}   # auto's all-n run
    assert {(c, n, r) for c, n, r in got if c == "small"} == {("small", 1, 1), ("small", 2, 1), ("small", 2, 2)}
    assert max(n for c, n, _ in got if c == "big") == 4 and min(n for c, n, _ in got if c == "big") == 2
    assert all(n >= 2 * r for c, n, r in got if c == "thin")


def test_max_n_and_size_together_are_refused(run):
    assert "contradict" in _error(run("verify", "--claims", "mine.py", "--max-n", "3", "--size", "2,1"))
