"""Class 7 (engine privileges through the live Trace): claim code edits the args of its residual's node
in the live graph, consistently (index updated), so the graph says In - In while Python computed XXᵀ - In.

c7e-false: residual XXᵀ − I_n  (FALSE for r < n: XXᵀ has rank r).  Truth: numpy, tr(XXᵀ − I) = r − n ≠ 0.
c7e-true:  residual XᵀX − I_r  (TRUE), same edit (control).
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2, r_max=1)


def _edit(s, R, a, b):
    t = object.__getattribute__(s, "_t")
    Tr = type(R)
    g = t.g
    i = Tr._r.__get__(R).i
    old = (g.ops[i], g.args[i])
    new_args = (Tr._r.__get__(a), Tr._r.__get__(b))
    del g.index[old]
    g.args[i] = new_args
    g.index[(g.ops[i], new_args)] = i


@claim("c7e-false", kind="id", sizes=SZ)
def c7e_false(s):
    """FALSE: XXᵀ = I_n."""
    I = s.In
    R = s.X @ s.X.T - I
    _edit(s, R, I, I)
    return {"r": R}


@claim("c7e-true", kind="id", sizes=SZ)
def c7e_true(s):
    """TRUE: XᵀX = I_r."""
    I = s.Ir
    R = s.X.T @ s.X - I
    _edit(s, R, I, I)
    return {"r": R}
