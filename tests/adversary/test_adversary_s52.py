"""Adversarial review of stop 52: the exact method's constrained-flow solves stay in the flint backend
(``systems._Algebra.solve`` takes M⁻¹B there, ``_Layout.assemble`` cuts the solution there).

A user's claims file (flow_solves_in_flint.py) states, through ``euler_lagrange``, two false accelerations of
the double Neumann system (Λ in place of Λᵀ; the sign of AY), and two ill-posed ones (a kinetic form that is
identically 0; every constraint twice, so the multipliers' matrix is singular).  No method may pass any of
them: the false ones fail with a witness, the ill-posed ones are an error (exact) or undecided (the point
methods: every point is degenerate).  The true acceleration (the printed Ẍ = −AX + XΛᵀ) is the positive
control: it passes under every method, so the runs do test the solve."""
from __future__ import annotations

from adversary_cli import PASSING, verdicts_each

FILE = "flow_solves_in_flint.py"
METHODS = ("exact", "modular", "rational", "float")


def test_false_and_ill_posed_flows_through_the_solve_pass_no_method():
    got = verdicts_each(FILE, METHODS, size="4,2")
    for method in METHODS:
        v = got[method]
        assert v["el-transposed-lambda"] == "fails", (method, v)
        assert v["el-sign"] == "fails", (method, v)
        for cid in ("el-degenerate-kinetic", "el-repeated-constraints"):
            assert v[cid] not in PASSING, (method, cid, v)
        assert v["el-true-control"] in PASSING, (method, v)
    assert got["exact"]["el-degenerate-kinetic"] == "error"
    assert got["exact"]["el-repeated-constraints"] == "error"
    assert got["exact"]["el-true-control"] == "proved"
