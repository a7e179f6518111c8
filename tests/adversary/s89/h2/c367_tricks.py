"""s89h2: classes 3 (exceptions), 4 (state), 6 (pickling), 7 (engine frames) through Python features.
Every claim's residual, when it is returned at all, is FALSE (XXᵀ − I_n at r < n, or tr PᵀP at n ≥ 2) unless
marked TRUE; a pass of a FALSE claim is a wrong verdict.
 c3-sysexit (FALSE): computes XXᵀ − I_n, then raises SystemExit(0) in the second trace (a module counter).
 c3-exit-first (FALSE): os._exit(0) at the first trace.
 c3-kbint (FALSE): raises KeyboardInterrupt at the second trace.
 c3-baseexc-caught (FALSE): catches BaseException around an out-of-range entry read X[9, 9] and returns XXᵀ − I_n.
 c4-thread (FALSE): a thread started by the claim swaps the returned dict's value for the TRUE residual XᵀX − I_r
    after 0.05 s (the dict holds the FALSE XXᵀ − I_n when returned).
 c4-dict-subclass (FALSE): returns a dict subclass whose items()/values() give XᵀX − I_r (TRUE) while __getitem__
    gives XXᵀ − I_n (FALSE), and the reverse variant c4-dict-subclass2.
 c4-gc-callback (FALSE): a gc callback that, at every collection, returns; weakref.finalize on a tracer; both
    harmless unless the engine reads state they change.
 c6-copyreg (FALSE): copyreg.pickle registered for the tracer's class, then pickle.dumps(X) (looks at what the
    reducer receives) and pickle.loads into the residual.
 c7-engine-filename (FALSE): the claim body is compiled with co_filename inside the package and __name__
    'stiefelsym.ir.trace', then run (frames that look like the engine's).
"""
import copyreg
import gc
import os
import pickle
import sys
import threading
import time
import weakref
from stiefelsym import admissible, claim

RLT = admissible(n_max=3, n_min=2, where=lambda n, r: r < n, condition="r < n")
_N = {"sysexit": 0, "kbint": 0, "exitfirst": 0}


def _false(s):
    return s.X @ s.X.T - s.In


@claim("c3-sysexit", kind="id", sizes=RLT)
def c3_sysexit(s):
    """FALSE: XXᵀ = I_n; SystemExit(0) at the second trace."""
    _N["sysexit"] += 1
    R = _false(s)
    if _N["sysexit"] == 2:
        raise SystemExit(0)
    return {"r": R}


@claim("c3-exit-first", kind="id", sizes=RLT)
def c3_exit_first(s):
    """FALSE: XXᵀ = I_n; os._exit(0) at the first trace."""
    _N["exitfirst"] += 1
    if _N["exitfirst"] == 1:
        sys.stdout.flush()
        os._exit(0)
    return {"r": _false(s)}


@claim("c3-kbint", kind="id", sizes=RLT)
def c3_kbint(s):
    """FALSE: XXᵀ = I_n; KeyboardInterrupt at the second trace."""
    _N["kbint"] += 1
    if _N["kbint"] == 2:
        raise KeyboardInterrupt
    return {"r": _false(s)}


@claim("c3-baseexc-caught", kind="id", sizes=RLT)
def c3_baseexc_caught(s):
    """FALSE: XXᵀ = I_n (an entry read out of range, caught as BaseException)."""
    try:
        s.X[9, 9]
    except BaseException:
        pass
    return {"r": _false(s)}


@claim("c4-thread", kind="id", sizes=RLT)
def c4_thread(s):
    """FALSE: XXᵀ = I_n; a thread swaps the dict's value afterwards."""
    out = {"r": _false(s)}
    true = s.X.T @ s.X - s.Ir

    def later():
        time.sleep(0.05)
        out["r"] = true
    threading.Thread(target=later, daemon=True).start()
    return out


class _Two(dict):
    def __init__(self, shown, real):
        super().__init__(r=real)
        self._shown = shown

    def items(self):
        return [("r", self._shown)]

    def values(self):
        return [self._shown]

    def __iter__(self):
        return iter(["r"])


@claim("c4-dict-subclass", kind="id", sizes=RLT)
def c4_dict_subclass(s):
    """FALSE: a dict subclass: __getitem__ gives XXᵀ − I_n, items()/values() give XᵀX − I_r."""
    return _Two(s.X.T @ s.X - s.Ir, _false(s))


@claim("c4-dict-subclass2", kind="id", sizes=RLT)
def c4_dict_subclass2(s):
    """FALSE: a dict subclass: items()/values() give XXᵀ − I_n, __getitem__ gives XᵀX − I_r (the claim as a
    dict reads XᵀX − I_r; as items() XXᵀ − I_n: recorded, either pass under every reading is a hole)."""
    return _Two(_false(s), s.X.T @ s.X - s.Ir)


@claim("c4-gc-callback", kind="id", sizes=RLT)
def c4_gc_callback(s):
    """FALSE: XXᵀ = I_n, with a gc callback and a weakref.finalize on the residual."""
    R = _false(s)
    gc.callbacks.append(lambda phase, info: None)
    weakref.finalize(s, lambda: None)
    gc.collect()
    return {"r": R}


@claim("c6-copyreg", kind="id", sizes=RLT)
def c6_copyreg(s):
    """FALSE: XXᵀ = I_n, through a copyreg reducer of the tracer's class."""
    R = _false(s)
    seen = []
    copyreg.pickle(type(R), lambda x: (seen.append(x) or (str, ("x",))))
    try:
        pickle.loads(pickle.dumps(R))
    except Exception:
        pass
    return {"r": seen[0] if seen else R}


_SRC = '''
def body(s):
    return {"r": s.X @ s.X.T - s.In}
'''


@claim("c7-engine-filename", kind="id", sizes=RLT)
def c7_engine_filename(s):
    """FALSE: XXᵀ = I_n, computed by code whose frames look like the engine's."""
    T = sys.modules['stiefelsym.ir.trace']
    g = {"__name__": "stiefelsym.ir.trace", "__builtins__": __builtins__}
    exec(compile(_SRC, T.__file__, "exec"), g)
    return g["body"](s)
