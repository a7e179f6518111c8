"""Class 7 without a single leading-underscore name: gc.get_referents(scene) gives the live Trace (its slot),
whose public attribute g is the graph (ops, args, index: public names); gc.get_referents(tracer) gives its Ref,
whose public attribute i is the node number.  The residual's node is rewritten, consistently, to In − In.

c7g-false: residual XXᵀ − I_n (FALSE for r < n; numpy: truth_numpy_output.txt, XX^T - I_n).
c7g-true:  residual XᵀX − I_r (TRUE), the same edit (control).
c7g-nonzero (FALSE statement of non-vanishing, expect="nonzero"): tr(PᵀP) + 1 ≠ 0 is TRUE; the edit makes its
   graph 1 − 1 = 0 (the residual is written tr(PᵀP) − (−1), a sub node) so that a pass of this TRUE claim turns into `fails` (a false refutation).
"""
import gc
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2, r_max=1)


def _trace_of(s):
    return next(o for o in gc.get_referents(s) if hasattr(o, "g") and hasattr(o.g, "ops"))


def _ref_of(x):
    return next(o for o in gc.get_referents(x) if type(o).__name__ == "Ref")


def _edit(s, R, a, b):
    g = _trace_of(s).g
    i = _ref_of(R).i
    old = (g.ops[i], g.args[i])
    new = (_ref_of(a), _ref_of(b))
    del g.index[old]
    g.args[i] = new
    g.index[(g.ops[i], new)] = i


@claim("c7g-false", kind="id", sizes=SZ)
def c7g_false(s):
    """FALSE: XXᵀ = I_n."""
    I = s.In
    R = s.X @ s.X.T - I
    _edit(s, R, I, I)
    return {"r": R}


@claim("c7g-true", kind="id", sizes=SZ)
def c7g_true(s):
    """TRUE: XᵀX = I_r."""
    I = s.Ir
    R = s.X.T @ s.X - I
    _edit(s, R, I, I)
    return {"r": R}


@claim("c7g-nonzero", kind="not", expect="nonzero", sizes=SZ)
def c7g_nonzero(s):
    """TRUE: tr(PᵀP) + 1 ≠ 0 (it is ≥ 1)."""
    one = s.q(1)
    R = s.tr(s.P.T @ s.P) - s.q(-1)        # a "sub" node: rewritten to one − one
    _edit(s, R, one, one)
    return {"r": R}
