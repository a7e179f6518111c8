"""Class 8 base: honest records to forge.  k8-false: XXᵀ = I_n (FALSE at r < n); k8-true: XᵀX = I_r (TRUE)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("k8-false", kind="id", sizes=SZ)
def k8_false(s):
    """FALSE at r < n: XXᵀ = I_n."""
    return {"r": s.X @ s.X.T - s.In}


@claim("k8-true", kind="id", sizes=SZ)
def k8_true(s):
    """TRUE: XᵀX = I_r."""
    return {"r": s.X.T @ s.X - s.Ir}
