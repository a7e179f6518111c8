"""False claims whose residual is an off-diagonal entry of XᵀAX, read without an entry read: constant
columns built with s.mat under the opaque space "r+so" (a block of R^r and a named coordinate space)
pick the entries.  In the equivariant chart with the O(r) reduction A11 = X0ᵀAX0 is diagonal."""
from stiefelsym import admissible, block, claim

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def pick(s, M, i, j):
    """E_iᵀ M E_j for an r x r matrix M (r = 2) through blocks tagged r+so."""
    z_col = s.zeros(2, 1, ("r", "so"))
    z_row = s.zeros(1, 2, ("so", "r"))
    ci = s.mat([[1 if k == i else 0] for k in range(3)], ("r+so", "?"))
    cj = s.mat([[1 if k == j else 0] for k in range(3)], ("r+so", "?"))
    left = ci.T @ block([[M], [z_row]])          # E_iᵀ M   (? x r)
    right = block([[s.Ir, z_col]]) @ cj          # E_j      (r x ?)
    return s.tr(left @ right)


@claim("adv-s32b-opaque-offdiag", kind="id", sizes=R2, statement="(XᵀAX)_12 = 0")
def opaque_offdiag(s):
    """False: XᵀAX is not diagonal."""
    return {"r": pick(s, s.X.T @ s.A @ s.X, 0, 1)}


@claim("adv-s32b-opaque-diag-control", kind="id", sizes=R2, statement="(XᵀX)_12 = 0")
def opaque_control(s):
    """True (XᵀX = I_r): the entry picking itself is sound."""
    return {"r": pick(s, s.X.T @ s.X, 0, 1)}



@claim("adv-s32b-opaque-offdiag-metric", kind="id", sizes=R2, realization="metric",
       statement="(XᵀA⁻¹X)_12 = 0")
def opaque_offdiag_metric(s):
    """False: the same entry picking in the metric realization, whose chart has long diagonalized B11
    (B = A⁻¹) by O(r) acting on the right."""
    return {"r": pick(s, s.X.T @ s.Ainv @ s.X, 0, 1)}
