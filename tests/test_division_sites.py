"""A division by an expression that vanishes on T*V names that expression, in the paper's notation, in the
verdict's message of every fixed-size method (the graph is the claim: the name is read from it, the same
whatever the method or the run)."""
import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one


def _claim(func):
    return Claim(id="pole", paper=("prep",), kind="id", section="t", func=func, sizes=admissible(4))


def scalar_pole(s):
    return {"q": s.tr(s.P.T @ s.P) / (s.tr(s.X.T @ s.X) - s.r)}


def singular_inverse(s):
    return {"q": (s.X.T @ s.P + s.P.T @ s.X).inv()}


def pole_in_a_hamiltonian(s):
    def H(t):
        return t.tr(t.P.T @ t.P) / (t.tr(t.X.T @ t.X) - t.r)
    return {"q": s.d(lambda t: t.Phi, s.dirac_flow(H))}


CASES = [(scalar_pole, "the division by tr(XᵀX) − r"), (singular_inverse, "the inverse of XᵀP + PᵀX"),
         (pole_in_a_hamiltonian, "the division by tr(XᵀX) − r")]


@pytest.mark.parametrize("func,where", CASES, ids=[f.__name__ for f, _ in CASES])
@pytest.mark.parametrize("method", ["exact", "rational", "modular", "float"])
def test_the_division_is_named(func, where, method):
    res = run_one(_claim(func), Size(3, 2), method, 0)
    assert res.verdict in ("error", "inconclusive"), (res.verdict, res.message)
    assert where in res.message, res.message


def test_a_claim_without_a_pole_is_unchanged():
    """The name is given only where a division raised: a true claim with a division passes as before."""
    def fine(s):
        return {"q": s.tr(s.X.T @ s.X) / (s.tr(s.P.T @ s.P) + 1) - s.r / (s.tr(s.P.T @ s.P) + 1)}
    for method in ("exact", "modular"):
        assert run_one(_claim(fine), Size(3, 2), method, 0).verdict in ("proved", "checked")
