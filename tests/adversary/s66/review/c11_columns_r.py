# ruff: noqa
"""The free method's column letters E_i (twisted.basis_vector) for a claim stated at r = 1 and r = 2: a statement
true at r = 2 and false at r = 1, and the converse."""
from stiefelsym import admissible, claim, twisted

S12 = admissible(n_max=3, r_in=(1, 2))


@claim("c11-true-at-2-only", kind="id", sizes=S12)
def t2(s):
    """tr(I_r - E1 E1^T) = 1: true at r = 2, false at r = 1 (there it is 0 = 1)."""
    E1 = twisted.basis_vector(s, 0)
    return {"x": s.tr(s.Ir - E1 @ E1.T) - 1}


@claim("c11-true-at-1-only", kind="id", sizes=S12)
def t1(s):
    """X E1 E1^T X^T = X X^T: true at r = 1, false at r = 2."""
    E1 = twisted.basis_vector(s, 0)
    return {"x": s.X @ E1 @ E1.T @ s.X.T - s.X @ s.X.T}


@claim("c11-last-true-at-2", kind="id", sizes=S12)
def l2(s):
    """tr(E_r E_r^T) + tr(E1 E1^T) = 2: true at r = 2, false at r = 1 (E_r = E_1 there: 2 = 2, true!)."""
    Er = twisted.last_basis_vector(s)
    E1 = twisted.basis_vector(s, 0)
    return {"x": s.tr(Er.T @ E1) - 0}
