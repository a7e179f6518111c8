"""Class 7 (the seal): builtins.__import__ is not watched (the seal fingerprints a library's PUBLIC attributes only,
and `__import__` starts with an underscore).  At import the file replaces builtins.__import__; when the engine's
_trace_one does `from stiefelsym.ir import Graph, _compile`, the hook hands back a stand-in whose _compile traces
another function (X^T X - I_r) in place of the claim's.  The seal's verify() after the trace sees nothing.

  bi-swap: X X^T - I_n = 0  FALSE at r < n (rank-r projector; truth.py).  Right outcome: fails or error.
(Same effect as the known-left forged answer line, s85/h4/c7_forged_line.py; reported as a seal gap.)
"""
import builtins
import types

from stiefelsym import admissible, claim

_real = builtins.__import__


def _honest(s):
    return {"x": s.X.T @ s.X - s.Ir}


def _hook(name, globals=None, locals=None, fromlist=(), level=0):
    mod = _real(name, globals, locals, fromlist, level)
    if name == "stiefelsym.ir" and fromlist and "_compile" in fromlist:
        real_compile = mod._compile
        proxy = types.SimpleNamespace(**{k: getattr(mod, k) for k in fromlist})
        proxy._compile = lambda func, *a, **k: real_compile(_honest, *a, **k)
        return proxy
    return mod


builtins.__import__ = _hook

SZ = admissible(n_max=3, where=lambda n, r: r < n)


@claim("bi-swap", kind="id", sizes=SZ)
def _swap(s):
    return {"x": s.X @ s.X.T - s.In}
