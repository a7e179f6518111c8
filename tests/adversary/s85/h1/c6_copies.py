"""Class 6: copying and introspecting tracer values in the claim (the trace runs in a child with no numbers).

cp-copy-t     copy.copy(XᵀX) − I_r                         TRUE  (a copy of a traced value is the same value)
cp-deep-f     deepcopy(X)ᵀ·deepcopy(P)                     FALSE (XᵀP ≠ 0 at r ≥ 2... at r = 1 XᵀP = 0: stated r ≥ 2)
cp-pickle     pickle round trip of XᵀX, minus I_r          TRUE if allowed (expected: refused)
cp-weak-t     weakref.ref(X)()ᵀX − I_r                     TRUE
cp-reduce     X.__reduce_ex__(4) rebuilt                   refused or TRUE
cp-frames     a value found in a caller's frame (inspect): the engine frames' locals are scanned for a Tracer that
              is not the claim's own, and added ×0 — a read of an engine value; expected refused or harmless.
"""
import copy
import inspect
import pickle
import weakref

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, r_min=2)


@claim("cp-copy-t", kind="id", sizes=SZ)
def cp_copy_t(s):
    M = copy.copy(s.X.T @ s.X)
    return {"x": M - s.Ir}


@claim("cp-deep-f", kind="id", sizes=SZ)
def cp_deep_f(s):
    return {"x": copy.deepcopy(s.X).T @ copy.deepcopy(s.P)}


@claim("cp-pickle", kind="id", sizes=SZ)
def cp_pickle(s):
    M = pickle.loads(pickle.dumps(s.X.T @ s.X))
    return {"x": M - s.Ir}


@claim("cp-weak-t", kind="id", sizes=SZ)
def cp_weak_t(s):
    X = s.X
    return {"x": weakref.ref(X)().T @ X - s.Ir}


@claim("cp-reduce", kind="id", sizes=SZ)
def cp_reduce(s):
    f, args = s.X.__reduce_ex__(4)[:2]
    Y = f(*args)
    return {"x": Y.T @ Y - s.Ir}


@claim("cp-frames", kind="id", sizes=SZ)
def cp_frames(s):
    found = []
    fr = inspect.currentframe().f_back
    while fr is not None and len(found) < 50:
        for v in list(fr.f_locals.values()):
            if type(v).__name__ == "Tracer" and v is not s:
                found.append(v)
        fr = fr.f_back
    out = s.X.T @ s.X - s.Ir
    for v in found:
        try:
            out = out + v * 0
        except Exception:  # noqa: BLE001
            pass
    return {"x": out}
