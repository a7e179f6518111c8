"""Symbolic solves larger than 3x3 that the exact method now takes when at most 3 rows cover their
off-diagonal pattern (μI − A in the chart with A11, A22 diagonal is an arrowhead): the resolvent identity
(true), the same with a factor 2 (false), and the inverse of a singular matrix whose pattern is covered
(A X (XᵀAX)⁻¹ Xᵀ A has rank r): M⁻¹M = I must never pass."""
from stiefelsym import admissible, claim

N5 = admissible(n_max=5, n_min=5, r_min=2, r_max=2, condition="n = 5, r = 2")
N4 = admissible(n_max=4, n_min=4, r_min=2, r_max=2, condition="n = 4, r = 2")


@claim("adv-s32b-core-resolvent", kind="id", sizes=N5, statement="(λI − A)R(λ) = I = R(λ)(λI − A)")
def core_resolvent(s):
    """True."""
    R = s.resolvent(s.lam)
    M = s.lam * s.In - s.A
    return {"l": M @ R - s.In, "r": R @ M - s.In}


@claim("adv-s32b-core-resolvent-false", kind="id", sizes=N5, statement="(λI − A)R(λ)X = 2X")
def core_resolvent_false(s):
    """False (a factor 2)."""
    return {"r": (s.lam * s.In - s.A) @ s.resolvent(s.lam) @ s.X - 2 * s.X}


@claim("adv-s32b-core-singular", kind="id", sizes=N4, statement="M⁻¹M = I for M = AX(XᵀAX)⁻¹XᵀA")
def core_singular(s):
    """False: M has rank r < n (no inverse)."""
    M = s.A @ s.X @ (s.X.T @ s.A @ s.X).inv() @ s.X.T @ s.A
    return {"r": M.inv() @ M - s.In}
