"""Class 8 base: one true and one false claim, for forged results files.
c8-t  XᵀX − I_r = 0  TRUE;   c8-f  XXᵀ − I_n = 0  FALSE at r < n (TRUE at r = n)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=2)


@claim("c8-t", kind="id", sizes=SZ)
def c8_t(s):
    return {"x": s.X.T @ s.X - s.Ir}


@claim("c8-f", kind="id", sizes=SZ)
def c8_f(s):
    return {"x": s.X @ s.X.T - s.In}
