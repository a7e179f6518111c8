"""Class 6/7 (what a claim reaches from a Tracer): rewrite the live trace's graph before it is sealed.

g-false: residual X Xᵀ − I_n (FALSE at r < n: rank of XXᵀ is r), node swapped with X − X.
g-true:  residual XᵀX − I_r (TRUE), same swap (control: must stay proved).
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


def _swap(s, a, b):
    t = object.__getattribute__(s, "_t")
    Tr = type(a)
    ia = Tr._r.__get__(a).i
    ib = Tr._r.__get__(b).i
    g = t.g
    g.ops[ia], g.args[ia] = g.ops[ib], g.args[ib]


@claim("g-false", kind="id", sizes=SZ)
def g_false(s):
    """FALSE: XXᵀ = I_n."""
    R = s.X @ s.X.T - s.In
    Z = s.In - s.In
    _swap(s, R, Z)
    return {"r": R}


@claim("g-true", kind="id", sizes=SZ)
def g_true(s):
    """TRUE: XᵀX = I_r."""
    R = s.X.T @ s.X - s.Ir
    Z = s.Ir - s.Ir
    _swap(s, R, Z)
    return {"r": R}
