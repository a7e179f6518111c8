"""Class 5 / expect="nonzero": statements that something does NOT vanish, where it does vanish identically, written with
heavy cancellation (terms 2^k times larger than the residual) so that floating point sees a nonzero remainder.
Each is FALSE (the residual is identically 0); a `proved`/`numeric` would be wrong.

nz-big-f      (X·B + X) − X·B − X,   B = 2^60            FALSE statement (residual 0)
nz-mul-f      (XᵀX·B + I_r)·(XᵀX·B − I_r) − B²·(XᵀX)² + I_r    FALSE (0 on V(n, r)); 2^120 terms
nz-pow-f      tr((Ψ·B)(Ψ·B)) − B²·tr(ΨΨ)  B = 2^200      FALSE (0)
nz-true-t     X·2^-60 (twin: TRUE nonzero)
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)
B = 2 ** 60


@claim("nz-big-f", kind="not", expect="nonzero", sizes=SZ)
def big_f(s):
    return {"x": (s.X * B + s.X) - s.X * B - s.X}


@claim("nz-mul-f", kind="not", expect="nonzero", sizes=SZ)
def mul_f(s):
    G = s.X.T @ s.X
    return {"x": (G * B + s.Ir) @ (G * B - s.Ir) - (G @ G) * (B * B) + s.Ir}


@claim("nz-pow-f", kind="not", expect="nonzero", sizes=SZ)
def pow_f(s):
    C = 2 ** 200
    return {"x": s.tr((s.Psi * C) @ (s.Psi * C)) - s.tr(s.Psi @ s.Psi) * (C * C)}


@claim("nz-true-t", kind="not", expect="nonzero", sizes=SZ)
def true_t(s):
    from fractions import Fraction
    return {"x": s.X * Fraction(1, 2 ** 60)}
