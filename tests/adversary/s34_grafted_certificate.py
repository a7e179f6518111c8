"""Fourth round (AJ): a dimension-free certificate moved to another claim.  The independent checker accepts any
certificate that expands to its own residual; nothing in the certificate names the claim.  The false claim's
free record (undecided) edited to `proved` with the true claim's certificate, reductions and derivation is
rendered by `stiefelsym report` as proved for every n and r unless the certificate is bound to the claim."""
from stiefelsym import admissible, claim

S = admissible(n_max=3)


@claim("adv-s34-graft-true", paper="t", kind="id", sizes=S, statement="X X^T X = X")
def graft_true(s):
    """True: X Xᵀ X = X (Xᵀ X = I_r)."""
    return {"x": s.X @ s.X.T @ s.X - s.X}


@claim("adv-s34-graft-false", paper="t", kind="id", sizes=S, statement="X X^T P = P")
def graft_false(s):
    """False for r < n: X Xᵀ P = P (the projector X Xᵀ is the identity at r = n only)."""
    return {"x": s.X @ s.X.T @ s.P - s.P}


@claim("adv-s34-graft-false-metric", paper="t", kind="id", sizes=S, realization="metric",
       statement="X^T A^-1 X = I_r")
def graft_false_metric(s):
    """False: Xᵀ A⁻¹ X = I_r (the metric's Gram matrix of X is not the identity)."""
    return {"x": s.X.T @ s.Ainv @ s.X - s.identity(s.r)}


@claim("adv-s34-graft-true-metric", paper="t", kind="id", sizes=S, realization="metric",
       statement="X^T X X^T A^-1 P + P^T A^-1 X = 0")
def graft_true_metric(s):
    """True: XᵀX XᵀA⁻¹P + PᵀA⁻¹X = 0 (cond_XP2 and XᵀX = I_r)."""
    return {"x": s.X.T @ s.X @ s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X}
