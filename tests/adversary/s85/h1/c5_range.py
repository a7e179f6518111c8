"""Class 5: constants inside float64's range whose products leave it (the constant pass reads constants one by one).

rg-sq-under-f   (cX)(cX)ᵀ with c = 2^-600: c²XXᵀ, c² = 2^-1200 underflows in float64   FALSE (nonzero)
rg-sq-under-t   (cX)(cX)ᵀ − c²·XXᵀ written with c2 = 2^-1200 as one constant             TRUE
rg-tr-under-f   tr(XᵀX)·c·c·c (c = 2^-400)                                               FALSE (= r·2^-1200)
rg-over-t       (dX)ᵀ(dX) − d²·I_r with d = 2^600 (d² overflows)                         TRUE
rg-over-f       (dX)ᵀ(dX) − d²·I_r + I_r                                                  FALSE (= I_r)
rg-pow-f        X·(c^3) via ** : (c·I_r)**3 with c = 2^-400 applied to X                  FALSE
rg-mixed-f      (c·X + X·2^-1100·2^1100 ...) : X·(2^-1074)·(2^-1074)·2^2148 − X + X... see body FALSE
"""
from fractions import Fraction
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)
c = Fraction(1, 2 ** 600)
c4 = Fraction(1, 2 ** 400)
d = 2 ** 600


@claim("rg-sq-under-f", kind="id", sizes=SZ)
def sq_under_f(s):
    Y = s.X * c
    return {"x": Y @ Y.T}


@claim("rg-sq-under-t", kind="id", sizes=SZ)
def sq_under_t(s):
    Y = s.X * c
    return {"x": Y @ Y.T - (s.X @ s.X.T) * (c * c)}


@claim("rg-tr-under-f", kind="id", sizes=SZ)
def tr_under_f(s):
    return {"x": s.tr(s.X.T @ s.X) * c4 * c4 * c4}


@claim("rg-over-t", kind="id", sizes=SZ)
def over_t(s):
    Y = s.X * d
    return {"x": Y.T @ Y - s.Ir * d * d}


@claim("rg-over-f", kind="id", sizes=SZ)
def over_f(s):
    Y = s.X * d
    return {"x": Y.T @ Y - s.Ir * d * d + s.Ir}


@claim("rg-pow-f", kind="id", sizes=SZ)
def pow_f(s):
    M = s.Ir * c4
    return {"x": s.X @ (M ** 3)}


@claim("rg-mixed-f", kind="id", sizes=SZ)
def mixed_f(s):
    # (X·t)·u where t = 2^-1000, u = 2^-1000: X·2^-2000 (no single constant outside [2^-1074, 2^1024))
    t = Fraction(1, 2 ** 1000)
    return {"x": (s.P * t) * t * (2 ** 900) * (2 ** 900)}   # = P·2^-200, nonzero
