# ruff: noqa
from stiefelsym import admissible, claim
SZ = admissible(n_min=3, n_max=3, r_min=2, r_max=2)

def tiny(s, k):
    c, t = s.q(1, 2), s.q(1)
    for _ in range(k):
        t = t * c
    return t

@claim("fool-subnormal-false", kind="id", sizes=SZ)
def a(s):
    """FALSE: 2^-1100 (XᵀX) = 2^-1100 · 2 I_r."""
    t = tiny(s, 1100)
    return {"r": (s.X.T @ s.X) * t - s.Ir * (t * 2)}

@claim("fool-cancel-true", kind="id", sizes=SZ)
def b(s):
    """TRUE: (10^300 + 1) P − 10^300 P − P = 0 plus a tiny term that vanishes: (XᵀX − I)·2^-1100."""
    return {"r": (s.P * (10**300 + 1) - s.P * 10**300 - s.P), "t": (s.X.T @ s.X - s.Ir) * tiny(s, 1100)}

@claim("fool-nonzero-false", kind="id", sizes=SZ, expect="nonzero")
def c(s):
    """FALSE as a nonvanishing statement: (XᵀX − I_r)·2^-1100 ≠ 0."""
    return {"r": (s.X.T @ s.X - s.Ir) * tiny(s, 1100)}

@claim("fool-nonzero-true", kind="id", sizes=SZ, expect="nonzero")
def d(s):
    """TRUE: 2^-1100 · XᵀX ≠ 0."""
    return {"r": (s.X.T @ s.X) * tiny(s, 1100)}
