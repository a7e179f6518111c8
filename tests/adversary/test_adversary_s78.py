"""Stop 78's replays: the review's Euler-Lagrange equations of kinetic energies that are not quadratic forms with
constant coefficients (s78/review/el_*.py), and the stop's own files (s78/own/): derivatives and points that
mix derivative levels, and kinetic energies whose coefficients move with the position."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).parent / "s78"


def _records(path: Path, *args: str) -> dict:
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(path), "--jobs", "1",
                          "--format", "json", *args], capture_output=True, text=True, timeout=600)
    assert out.stdout.strip(), out.stderr[-2000:]
    return {(r["claim"], r.get("n"), r.get("r")): r for r in json.loads(out.stdout)["results"]}


NOT_QUADRATIC = "not a quadratic form in the velocities"
POSITION = "coefficients may depend on the position"


@pytest.mark.parametrize("method", ["exact", "modular", "float", "free"])
def test_euler_lagrange_of_a_linear_term_and_of_a_cubic_one(method):
    """Review W1: T = tr(ẊᵀẎ) + tr(GᵀẊ), a null Lagrangian added: free proved false accelerations (and check
    accepted the record), since it took d/dt ∂T/∂q̇ as ∂T/∂q̇ at q̇ ↦ q̈, which keeps the constant G.  It now
    subtracts ∂T/∂q̇ at q̇ = 0: the true accelerations are proved, the false ones are not.  Review W2:
    T = tr(ẊᵀẎ) + Ẋ₁₁Ẋ₂₁Ẏ₁₁: exact proved and modular checked false accelerations (the mass matrix, read from
    gradients at basis vectors, dropped the cubic term); a kinetic energy of degree above 2 in the velocities
    is now refused by every method, a cubic trace form by the dimension-free one too."""
    for name in ("el_linear_kinetic.py", "el_linear_complex.py"):
        for (cid, n, r), rec in _records(HERE / "review" / name, "--method", method).items():
            if cid.endswith("-true"):
                assert rec["verdict"] in ("proved", "checked", "numeric"), (name, cid, n, r, rec["verdict"])
            else:
                assert rec["verdict"] in ("fails", "undecided"), (name, cid, n, r, rec["verdict"])
    cubic = list(_records(HERE / "review" / "el_cubic_kinetic.py", "--method", method).values())
    cubic += list(_records(HERE / "own" / "kinetic_position.py", "o78-el-cubic-trace", "--method", method).values())
    for rec in cubic:
        assert rec["verdict"] in ("error", "undecided"), (rec["claim"], rec["verdict"])
        if method != "free" or rec["claim"] == "o78-el-cubic-trace":
            assert NOT_QUADRATIC in rec["message"], (rec["claim"], rec["message"])


@pytest.mark.parametrize("method", ["exact", "modular", "float", "free"])
def test_a_kinetic_energy_that_moves_with_the_position_is_refused(method):
    """The stop's own attempt: T reading the position (closed over, or through its own scene's double point) had
    its coefficients read at the point and the equations solved as if constant; refused when traced, for every
    method.  A constant coefficient (tr A) is accepted."""
    recs = _records(HERE / "own" / "kinetic_position.py", "--method", method)
    for (cid, n, r), rec in recs.items():
        if cid == "o78-el-cubic-trace":
            continue
        if cid == "o78-el-constant-ok":
            assert rec["verdict"] in ("proved", "checked", "numeric", "undecided"), (cid, n, r, rec["verdict"])
        else:
            assert rec["verdict"] == "error" and POSITION in rec["message"], (cid, n, r, rec["verdict"])


@pytest.mark.parametrize("method", ["exact", "modular", "float"])
def test_points_and_scalars_of_other_levels(method):
    """twisted.at_point(t, Xₜ, Pₜ) and at_point(t, X_s, P_s) (a value of the enclosing scene: a constant), and
    t's matrices times a number of w's level (lifted by the evaluator): true claims pass, false twins fail."""
    for name in ("at_point_levels.py", "scalar_of_inner_level.py"):
        for (cid, n, r), rec in _records(HERE / "own" / name, "--method", method).items():
            want = ("fails",) if cid.endswith("-false") else ("proved", "checked", "numeric")
            assert rec["verdict"] in want, (name, cid, n, r, rec["verdict"])
