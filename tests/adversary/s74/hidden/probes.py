# ruff: noqa
"""s74 probes: variants of claims.py that lean on the sizes (r = 1, r = n families, statements true only at small
n), with the verdict numpy expects in each docstring.  Helpers in _h74_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, elementary

from _h74_helpers import H_normal, block_M

ALL = admissible(n_max=5)


@claim("p74-cubic-small-n", kind="id", sizes=ALL, fails_at=lambda n, r: n >= 4 and r >= 2,
       erratum="Φ³ = ½tr(Φ²)Φ holds for n <= 3 (so(3)) and at r = 1 (rank 2) only")
def cubic_small_n(s):
    """Φ³ − ½tr(Φ²)Φ = 0: true for n <= 3 (every skew 3×3 matrix) and at r = 1, false for n >= 4, r >= 2.
    numpy: fails exactly at n >= 4, r >= 2; free must not prove it."""
    F = s.Phi
    return {"Phi^3 - tr(Phi^2)/2 Phi": F @ F @ F - F * (s.tr(F @ F) / 2)}


@claim("p74-cubic-r1-family", kind="id", sizes=admissible(n_max=5, r_max=1, condition="r = 1"))
def cubic_r1_family(s):
    """The same identity at r = 1 only: true for every n (free may prove it for every n at r = 1)."""
    F = s.Phi
    return {"Phi^3 - tr(Phi^2)/2 Phi": F @ F @ F - F * (s.tr(F @ F) / 2)}


@claim("p74-cubic-r2-family", kind="id", sizes=admissible(n_max=5, r_min=2, r_max=2, condition="r = 2"),
       fails_at=lambda n, r: n >= 4, erratum="false at r = 2 for n >= 4")
def cubic_r2_family(s):
    """At r = 2 only: true at n = 2, 3, false for n >= 4; free must not prove it."""
    F = s.Phi
    return {"Phi^3 - tr(Phi^2)/2 Phi": F @ F @ F - F * (s.tr(F @ F) / 2)}


@claim("p74-charpoly-r1", kind="id", sizes=admissible(n_max=5, r_max=1, condition="r = 1"))
def charpoly_r1(s):
    """r = 1: Φ·p_M(Φ) = 0 with M 2×2 (elementary(M, 2) without reading r): true for every n."""
    F = s.Phi
    M = block_M(s, s.X, s.P)
    e = elementary(s, M, 2)
    return {"Phi p_M(Phi)": F @ (F @ F * e[0] - F * e[1] + s.In * e[2])}


@claim("p74-charpoly-r1-no-factor", kind="id", sizes=admissible(n_max=5, r_max=1, condition="r = 1"),
       fails_at=lambda n, r: n >= 3, erratum="p_M(Φ) = 0 at r = 1 holds only for n <= 2")
def charpoly_r1_no_factor(s):
    """r = 1: p_M(Φ) = Φ² + (p, p)I = 0, true for n <= 2 only (at n = 1 Φ = 0 and P = 0); free must not prove it."""
    F = s.Phi
    M = block_M(s, s.X, s.P)
    e = elementary(s, M, 2)
    return {"p_M(Phi)": F @ F * e[0] - F * e[1] + s.In * e[2]}


@claim("p74-space-body-r-is-n", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def space_body_r_is_n(s):
    """r = n declared with r_is_n: Φ = XΨXᵀ and XᵀẊ = Ψ along the normal flow (true)."""
    X = s.X
    fl = s.dirac_flow(H_normal)
    return {"Phi - X Psi X^T": s.Phi - X @ s.Psi @ X.T, "X^T Xdot - Psi": X.T @ fl["X"] - s.Psi}


@claim("p74-space-body-minus-r-is-n", kind="id", sizes=admissible(n_max=5, r_is_n=True),
       fails_at=lambda n, r: n >= 2, erratum="Φ = −XΨXᵀ")
def space_body_minus_r_is_n(s):
    """r = n: Φ = −XΨXᵀ (false for n >= 2); free must not prove it."""
    return {"Phi + X Psi X^T": s.Phi + s.X @ s.Psi @ s.X.T}
