"""Class 6: pickling, new routes.  Each k6-* branches on what pickling reveals: if it learns a number of a size (or
anything of the run), it returns the FALSE XXᵀ − I_n, else the TRUE XᵀX − I_r.  k6-control is TRUE.

k6-copyreg: a reducer of the file's own for Tracer registered in copyreg.dispatch_table, then pickle.dumps(s.X)
k6-dim-copyreg: the same for Dim (the size), then pickle.dumps(s.n)
k6-closure: the trace's size function read through its closure cells (the number of n, if any)
k6-deepcopy: copy.deepcopy of a dict of tracers, then pickled with protocol 0
"""
import copy
import copyreg
import pickle

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


def _false_or_true(s, learned):
    if learned:
        return {"r": s.X @ s.X.T - s.In}
    return {"r": s.X.T @ s.X - s.Ir}


@claim("k6-copyreg", kind="id", sizes=SZ)
def k6_copyreg(s):
    X = s.X
    T = type(X)
    seen = []
    copyreg.dispatch_table[T] = lambda x: (seen.append(object.__getattribute__(x, "_shape")) or int, (0,))
    try:
        pickle.dumps(X)
    except Exception:
        pass
    finally:
        copyreg.dispatch_table.pop(T, None)
    learned = bool(seen) and any(getattr(d, "value", None) not in (None,) for d in seen[0])
    return _false_or_true(s, learned)


@claim("k6-dim-copyreg", kind="id", sizes=SZ)
def k6_dim_copyreg(s):
    d = s.n
    T = type(d)
    seen = []
    copyreg.dispatch_table[T] = lambda x: (seen.append(object.__getattribute__(x, "_expr")) or int, (0,))
    try:
        pickle.dumps(d)
    except Exception:
        pass
    finally:
        copyreg.dispatch_table.pop(T, None)
    learned = bool(seen) and getattr(seen[0], "value", None) is not None
    return _false_or_true(s, learned)


@claim("k6-closure", kind="id", sizes=SZ)
def k6_closure(s):
    t = object.__getattribute__(s, "_t")
    f = t._numbers
    cells = [c.cell_contents for c in (f.__closure__ or ())]
    learned = any(type(c) is int for c in cells)
    return _false_or_true(s, learned)


@claim("k6-deepcopy", kind="id", sizes=SZ)
def k6_deepcopy(s):
    d = copy.deepcopy({"x": s.X, "n": s.n})
    try:
        pickle.dumps(d, protocol=0)
        learned = True
    except Exception:
        learned = False
    return _false_or_true(s, learned)


@claim("k6-control", kind="id", sizes=SZ)
def k6_control(s):
    return {"r": s.X.T @ s.X - s.Ir}
