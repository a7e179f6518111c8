"""The symbolic Cayley chart reduced by O(r) acting on the right as well (2 <= r < n).

A graph that reads coordinates of ℝⁿ (the eigenvalues a_i of A = diag(a), an entry of X, a reflection
S_1) is evaluated by the exact method on the Cayley chart, X = [I − S11 − KᵀK; −2K] M⁻¹ with
M = I + S11 + KᵀK, whose r(r − 1)/2 parameters of S11 enter every entry of X through det M.  Where
the graph reads nothing of ℝʳ (:func:`stiefelsym.ir.passes.right_action_breaks` finds nothing), its
residuals are covariant under (X, P) ↦ (Xh, Ph), h ∈ O(r), and the chart with S11 = 0 suffices:
the points X(K)h fill a dense open set of V(n, r).  What is assumed is stated in every record
(:data:`REDUCTION`); a graph that reads ℝʳ (an entry of XᵀP, a determinant written with entries of
an r × r matrix) keeps the full chart.
"""
from __future__ import annotations

from typing import Any

from stiefelsym.ir.passes import right_action_breaks

#: the reduction stated in the record of a run on the chart
REDUCTION = (
    "rational parametrization reduced by O(r) acting on the right: X = [I - K^T K; -2K] M^{-1}, "
    "M = I + K^T K (K generic (n - r) x r; the Cayley chart of the first r columns of (I - S)(I + S)^{-1}, "
    "S = [[S11, -K^T], [K, 0]], at S11 = 0, so that the top block X1 = (I - K^T K)M^{-1} is symmetric); "
    "P = XW + (I - XX^T)Z (W skew, Z = [0; Z2] with Z2 arbitrary (n - r) x r), A = diag(a).  The map "
    "(K, h) -> X(K)h, h in O(r), has an injective differential at (0, I) onto the tangent space of the "
    "irreducible V(n, r) (dK gives [0; -2dK], h = exp(eta) gives [eta; 0], eta skew), and (X(K)h, Ph) "
    "with P as above is every cotangent vector at X(K)h (W -> h^T W h, Z -> Zh): the points of the chart "
    "moved by O(r) are dense in T*V(n, r).  The residuals are covariant under (X, P) -> (Xh, Ph) "
    "(every R^r side of a generic matrix moving with h, which keeps it generic), because the graph reads "
    "no coordinate of R^r: no entry or block of a matrix with a side on R^r, no matrix of given entries "
    "on R^r, no rank, no second, complex or double point, and no engine step but constants on R^n "
    "(S_1, diag(I_2, 0)); every other operation is a typed matrix operation, which commutes with the "
    "action, whatever the graph reads of R^n")


#: the reduction stated at r = n, where the chart is one point per orbit of O(n) acting on the right
REDUCTION_SQUARE = (
    "reduced by O(n) acting on the right (r = n): X = I, P = W (W skew generic n x n), A = diag(a).  Every "
    "point of T*V(n, n) = T*O(n) is (Ih, Wh) for h = X in O(n) (either component) and W = P X^T, skew "
    "because X^T P is: the chart moved by O(n) is all of T*V(n, n).  The residuals are covariant under "
    "(X, P) -> (Xh, Ph) (every R^r side of a generic matrix moving with h, which keeps it generic), because "
    "the graph reads no coordinate of R^r: no entry or block of a matrix with a side on R^r, no matrix of "
    "given entries on R^r, no rank, no second, complex or double point, and no engine step but constants on "
    "R^n (S_1, diag(I_2, 0)); every other operation is a typed matrix operation, which commutes with the "
    "action, whatever the graph reads of R^n")


def reduction(n: int, r: int) -> str:
    """The reduction stated in the record of a run on the right-reduced chart at (n, r)."""
    return REDUCTION_SQUARE if r == n else REDUCTION


def applies(graph: Any, realization: str | None, n: int, r: int) -> bool:
    """Whether the exact method may evaluate ``graph`` on the right-reduced Cayley chart: the standard
    realization, 2 <= r <= n (at r = 1 S11 is 0 already; at r = n the chart is X = I), and nothing in the
    graph that may break covariance under O(r) on the right (computed once per graph)."""
    if (realization or "standard") != "standard" or not 2 <= r <= n:
        return False
    breaks = graph.cache.get("right action breaks")
    if breaks is None:
        breaks = graph.cache["right action breaks"] = tuple(right_action_breaks(graph))
    return not breaks
