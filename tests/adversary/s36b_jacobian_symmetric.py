"""Round 6b: s.jacobian(F, symmetric=True) reads each matrix of F by its upper triangle (rows (i, j), j >= i,
of its first dimension): meant for symmetric F, whose lower triangle repeats the upper one.  Here F is not
symmetric (XᵀP, r x r) or not square (Xᵀ, r x n): the rank of its Jacobian read that way is not the rank of the
Jacobian of F."""
from stiefelsym import admissible, claim
from stiefelsym.ir.statements import Rank

SIZES = admissible(n_min=3, n_max=3, r_min=2, r_max=2)


@claim("adv-s36b-jacobian-symmetric-not-symmetric", kind="dim", sizes=SIZES)
def jacobian_symmetric_not_symmetric(s):
    """False: the 4 entries of XᵀP have 3 independent differentials at a generic point of T*V (they have 4:
    d(XᵀP) = dXᵀP + XᵀdP, and dP is free)."""
    return {"rank": Rank(s.mat(s.jacobian(lambda t: t.X.T @ t.P, True), ("?", "?")), 3, generic=True)}


@claim("adv-s36b-jacobian-symmetric-wide", kind="dim", sizes=SIZES)
def jacobian_symmetric_wide(s):
    """False: the 6 entries of Xᵀ (r x n) have 3 independent differentials (they have 6: they are coordinates)."""
    return {"rank": Rank(s.mat(s.jacobian(lambda t: t.X.T, True), ("?", "?")), 3, generic=True)}


@claim("adv-s36b-jacobian-symmetric-control", kind="dim", sizes=SIZES)
def jacobian_symmetric_control(s):
    """True: the 4 entries of XᵀP have 4 independent differentials (the Jacobian read entry by entry)."""
    return {"rank": Rank(s.mat(s.jacobian(lambda t: t.X.T @ t.P, False), ("?", "?")), 4, generic=True)}
