"""The diagonal chart of the symbolic method: a graph that reads no point of T*V spends the O(n)
reduction on A alone (A = diag(a)).  Negative controls: claims that hold for diagonal A only (they
read coordinates of R^n), claims that read a point, and corrupted statements."""
from __future__ import annotations

import pytest

from stiefelsym import admissible
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one
from stiefelsym.scene import PointRead, Scene

DIAGONAL = "A = diag(a_1..a_n) with the a_i free"


def _claim(id: str, func, kind: str = "id") -> Claim:
    return Claim(id=id, paper=(), kind=kind, section="t", func=func, sizes=admissible(7))


def _exact(func, n: int = 4, r: int = 2):
    return run_one(_claim("diag", func), Size(n, r), "exact", 0)


def test_the_chart_is_diagonal_and_refuses_every_point():
    s = Scene(5, 2, SymbolicField(), chart="equivariant", diagonal_A=True)
    A = s.A._a
    assert all(A[i, j] == 0 for i in range(5) for j in range(5) if i != j)
    assert all(A[i, i] != 0 for i in range(5))
    assert DIAGONAL in s.equivariant_reduction()
    for what in ("X", "P", "Phi", "Psi", "Y", "Q", "Zc", "DX"):
        with pytest.raises(PointRead):
            getattr(Scene(5, 2, SymbolicField(), chart="equivariant", diagonal_A=True), what)
    for bad in ({"chart": "cayley"}, {"chart": "equivariant", "right_reduction": True},
                {"chart": "equivariant", "realization": "metric"}):
        with pytest.raises(ValueError):
            Scene(5, 2, SymbolicField(), diagonal_A=True, **bad)


def _commutator_identity(s, corrupt: bool = False):
    """[A, [A, x]] = A²x − 2AxA + xA² for a generic x in gl(n); corrupt: the factor 2 is 1."""
    x = s.generic("x", "n", "n")
    A = s.A
    lhs = A @ (A @ x - x @ A) - (A @ x - x @ A) @ A
    return {"[A,[A,x]]": lhs - (A @ A @ x - A @ x @ A * (1 if corrupt else 2) + x @ A @ A)}


@pytest.mark.parametrize("n,r", [(4, 1), (5, 3)])
def test_a_point_free_identity_is_proved_on_the_diagonal_chart_and_its_corruption_fails(n, r):
    res = _exact(_commutator_identity, n, r)
    assert res.verdict == "proved", res.message
    assert any(DIAGONAL in d for d in res.reductions), res.reductions
    bad = _exact(lambda s: _commutator_identity(s, corrupt=True), n, r)
    assert bad.verdict == "fails", bad.message


def _comm(a, b):
    return a @ b - b @ a


ADVERSARIAL = {
    # covariant, and zero where X = X0 and A is diagonal at once, but not on T*V: O(n) moves X to X0
    # or diagonalizes A, not both, so a graph that reads a point must not get the diagonal chart
    "[X^T A X, X^T A^2 X]": lambda s: {"x": _comm(s.X.T @ s.A @ s.X, s.X.T @ s.A @ s.A @ s.X)},
    "[Y^T A Y, Y^T A^2 Y]": lambda s: {"x": _comm(s.Y.T @ s.A @ s.Y, s.Y.T @ s.A @ s.A @ s.Y)},
    "through Psi = X^T P - P^T X": lambda s: {
        "x": s.tr(_comm(s.X.T @ s.A @ s.X, s.X.T @ s.A @ s.A @ s.X) @ s.Psi)},
    "through Phi = P X^T - X P^T": lambda s: {
        "x": s.tr(_comm(s.A, s.Phi) @ _comm(s.A @ s.A, s.Phi)) - s.tr(_comm(s.A @ s.A, s.Phi) @ _comm(s.A, s.Phi))
        + s.tr(s.X.T @ _comm(s.A, s.X @ s.X.T) @ s.A @ s.A @ s.X)},
}


@pytest.mark.parametrize("what", sorted(ADVERSARIAL))
@pytest.mark.parametrize("method", ["exact", "auto"])
def test_claims_that_read_a_point_and_hold_only_for_diagonal_A_fail(what, method):
    res = run_one(_claim("adv", ADVERSARIAL[what]), Size(4, 2), method, 0)
    assert res.verdict == "fails", (what, res.verdict, res.message)
    assert not any(DIAGONAL in d for d in res.reductions or ()), res.reductions


def test_a_claim_that_reads_the_point_takes_the_chart_that_fixes_it():
    """tr(XᵀAX) − tr(A X Xᵀ) = 0 reads X: proved on the chart X = X0, never on the diagonal one; the
    false tr(XᵀAX) = tr(A)/n·r (true on no open set) fails."""
    res = _exact(lambda s: {"x": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A @ s.X @ s.X.T)}, 5, 2)
    assert res.verdict == "proved", res.message
    assert not any(DIAGONAL in d for d in res.reductions), res.reductions
    bad = _exact(lambda s: {"x": s.tr(s.X.T @ s.A @ s.X) * s.n - s.tr(s.A) * s.r}, 5, 2)
    assert bad.verdict == "fails", bad.message


def test_pencil_casimirs_takes_the_diagonal_chart_at_n_7():
    from stiefelsym.claims import load_catalog
    c = load_catalog().get("pencil-casimirs")
    res = run_one(c, Size(5, 2), "exact", 0)
    assert res.verdict == "proved", res.message
    assert any(DIAGONAL in d for d in res.reductions), res.reductions


def _commutes_with_a_generic_symmetric(s):
    """False: A commutes with every symmetric W.  On the diagonal chart only A is reduced: W = w + wᵀ stays a
    generic symmetric matrix (not diagonal), so the residual is nonzero there."""
    w = s.generic("w", "n", "n")
    return {"[A, w + w^T]": _comm(s.A, w + w.T)}


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_a_generic_matrix_is_not_reduced_with_a(method):
    res = run_one(_claim("diag-w", _commutes_with_a_generic_symmetric), Size(4, 2), method, 0)
    assert res.verdict == "fails", res.message
    assert any(DIAGONAL in d for d in res.reductions), res.reductions
