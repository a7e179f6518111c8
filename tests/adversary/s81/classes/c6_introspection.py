"""Class 6 (pickling / introspection of traced values), new tricks: deepcopy of the scene and of a tracer, the
object graph below a tracer (gc.get_referents, vars, __reduce_ex__), a size's repr through format(), and a second
scene built by the tracer's class from another tracer's internals.  Each -false claim returns XXᵀ − I_n (FALSE at
r < n) on one branch and XᵀX − I_r (TRUE) on the other, branching on what introspection reveals; the -true twin is
the true residual computed through the copied object.
"""
import copy
import gc
import pickle

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


def _t(s):
    return s.X.T @ s.X - s.Ir


def _f(s):
    return s.X @ s.X.T - s.In


@claim("c6-deepcopy-true", kind="id", sizes=SZ)
def c6_deepcopy_true(s):
    """TRUE: XᵀX − I_r through a deep copy of X (one matrix)."""
    Xc = copy.deepcopy(s.X)
    return {"r": Xc.T @ Xc - s.Ir}


@claim("c6-deepcopy-false", kind="id", sizes=SZ)
def c6_deepcopy_false(s):
    """FALSE: XcXcᵀ − I_n through a deep copy of the scene."""
    t = copy.deepcopy(s)
    return {"r": t.X @ t.X.T - s.In}


@claim("c6-referents-false", kind="id", sizes=SZ)
def c6_referents_false(s):
    """FALSE branch when the objects below X hold any int > 1 (a size number): a read of a size by the object graph."""
    seen, todo, found = set(), [s.X, s], False
    while todo and len(seen) < 5000:
        o = todo.pop()
        if id(o) in seen:
            continue
        seen.add(id(o))
        if type(o) is int and o in (2, 3):
            found = True
            break
        try:
            todo.extend(gc.get_referents(o))
        except Exception:
            pass
    return {"r": _f(s) if found else _t(s)}


@claim("c6-pickle-false", kind="id", sizes=SZ)
def c6_pickle_false(s):
    """FALSE branch when pickling (protocol 0..5, or __reduce_ex__) of X succeeds."""
    ok = False
    for proto in range(6):
        try:
            pickle.dumps(s.X, protocol=proto)
            ok = True
        except BaseException:
            pass
    try:
        s.X.__reduce_ex__(2)
        ok = True
    except BaseException:
        pass
    return {"r": _f(s) if ok else _t(s)}


@claim("c6-format-false", kind="id", sizes=SZ)
def c6_format_false(s):
    """FALSE branch when format()/f-string of the scene or of X's type mentions a digit."""
    try:
        txt = format(s) + repr(type(s.X).__dict__.keys()) + str(vars(s) if hasattr(s, "__dict__") else "")
    except BaseException:
        txt = ""
    return {"r": _f(s) if any(c in txt for c in "23") else _t(s)}
