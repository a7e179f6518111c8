"""A false claim that reads an entry of the twisted constraint bracket matrix: its rows and columns are the
scalar constraints in the fixed basis of Sym(r) (X^T X = I_r and X^T P + P^T X = 0, entry by entry), a named
coordinate space the engine does not record.  With the field strength F = XᵀAXD − (XᵀAXD)ᵀ, D = diag(1, 2)
(skew, as the engine requires since stop 54; F_12 = (XᵀAX)_12), the ε-term of the entry of (sym(XᵀP)_11,
sym(XᵀP)_12) is a multiple of (XᵀAX)_12, which is 0 in the exact method's chart with A11 diagonal; O(r)
acting on the right mixes the basis, so the entry is not covariant."""
from stiefelsym import admissible, claim, twisted

R2 = admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="n = 3, r = 2")


@claim("adv-s32b-cond-entry", kind="id", sizes=R2,
       statement="{φ_4, φ_5}_ε(F = XᵀAXD − DXᵀAX) = {φ_4, φ_5}_ε(F = 0)")
def cond_entry(s):
    """False: the two entries differ by ε times a multiple of (XᵀAX)_12."""
    M = s.X.T @ s.A @ s.X @ s.mat([[1, 0], [0, 2]], ("r", "r"))
    F = M - M.T
    C1 = twisted.constraint_bracket_matrix(s, F)
    C0 = twisted.constraint_bracket_matrix(s, s.zeros(2, 2, ("r", "r")))
    return {"r": C1[3][4] - C0[3][4]}


@claim("adv-s32b-cond-entry-metric", kind="id", sizes=R2, realization="metric", statement="{φ_1, φ_5}_0 = 0")
def cond_entry_metric(s):
    """False: an entry of the metric realization's constraint bracket matrix (s.constraint_bracket_matrix(),
    no field strength), 0 in the metric chart, which has long reduced by O(r) acting on the right."""
    return {"r": s.constraint_bracket_matrix()[0][4]}
