# ruff: noqa
"""Classes 3 (exceptions as a side channel), 6 (pickling) and 7 (spoofed __name__ / co_filename), new tricks.
Every claim returns a FALSE residual on the branch a trick would reach if it told methods or sizes apart, and
a TRUE one otherwise; the verdict must never be a pass of the false residual, nor a 'proved for all n, r'."""
import copy
import pickle
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=4, r_in=(2,))


def _true(s):
    return s.X.T @ s.X - s.Ir


def _false(s):
    return s.X.T @ s.P


@claim("c3-catch-zero-division", kind="id", sizes=S)
def c3_zd(s):
    """false as written (X^T P) unless dividing by the constant 0 raises, which it does on every method."""
    try:
        _ = s.X / (s.q(1) - 1)
        return {"x": _false(s)}
    except Exception:
        return {"x": _true(s)}


@claim("c3-catch-size-read", kind="id", sizes=S)
def c3_size(s):
    """reads int(n) in a try: symbolic sizes refuse it (caught), fixed sizes answer; at fixed sizes the residual is
    the true one, with symbolic sizes the false one (so free would see only the false one)... and vice versa:
    at fixed sizes FALSE, symbolically TRUE: the free method must not prove it for all n."""
    try:
        int(s.n)
        return {"x": _false(s)}
    except Exception:
        return {"x": _true(s)}


@claim("c3-catch-shape", kind="id", sizes=S)
def c3_shape(s):
    """M.shape raises with symbolic sizes (caught): FALSE at fixed sizes, TRUE symbolically."""
    try:
        s.X.shape
        return {"x": _false(s)}
    except Exception:
        return {"x": _true(s)}


@claim("c3-catch-mismatch-dims", kind="id", sizes=S)
def c3_dims(s):
    """an n x r matrix times a 2r-row one fits for some n only (refused symbolically): FALSE where it fits."""
    try:
        s.X @ s.zeros(2 * s.r, s.r)
        return {"x": _false(s)}
    except Exception:
        return {"x": _true(s)}


@claim("c6-reduce-ex-bypass", kind="id", sizes=S)
def c6(s):
    """object.__reduce_ex__ around the tracer's own __reduce__, copy.deepcopy, pickle: whatever they give, the
    statement returned is FALSE (X^T P)."""
    got = []
    for f in (lambda: object.__reduce_ex__(s.X, 2), lambda: copy.deepcopy(s.X), lambda: pickle.dumps(s.X, 5),
              lambda: copy.copy(s)):
        try:
            got.append(f())
        except Exception:
            got.append(None)
    return {"x": _false(s)}


_SRC = '''
def spoofed(s, _true, _false):
    try:
        t = object.__getattribute__(s, "_t")
        return {"x": _true(s)} if t is not None else {"x": _false(s)}
    except Exception:
        return {"x": _false(s)}
'''
_ns = {"__name__": "stiefelsym.ir.trace"}
exec(compile(_SRC, "/work/main/stiefelsym/ir/trace.py", "exec"), _ns)


@claim("c7-spoofed-engine-frame", kind="id", sizes=S)
def c7(s):
    """code whose module is named stiefelsym.ir.trace and whose file is the engine's: returns X^T X - I (TRUE) when
    it reads the scene's private trace; the statement is true either way... and its site is the engine's."""
    return _ns["spoofed"](s, _true, _false)
