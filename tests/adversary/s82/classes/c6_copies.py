"""Class 6 (pickling, introspection) on statements and MatrixFunctions.

 cp-asdict-false:  dataclasses.asdict(Rank(XXᵀ, r)) (deep-copies the matrix), its "matrix" used as a residual
                   minus XXᵀ... written: asdict(...)["matrix"] − XXᵀ + I_n = 0 : FALSE (= I_n).
 cp-asdict-true:   asdict(...)["matrix"] − XXᵀ = 0: TRUE (if the copy is the same graph) or refused.
 cp-pickle-rank:   pickle.dumps(Rank(...)) then branch: if it pickles, return the FALSE XXᵀ − I_n, else the TRUE
                   XᵀX − I_r; a refusal caught is still an error.  FALSE or error are right; proved is wrong only
                   if the graph is XXᵀ − I_n.
 cp-mf-copy-false: copy.deepcopy of a MatrixFunction after its gradient was checked, then the copy's value
                   swapped (object.__setattr__) and used: <∇h(x), x> = 4h_copy(x) with h_copy = ¼<y,y>... FALSE
                   (<∇h(x),x> = 2·½<x,x> = <x,x>; 4·¼<x,x> = <x,x>: TRUE!) — so the FALSE twin uses 8·h_copy = 2<x,x>.
 cp-mf-copy-true:  the same with 4·h_copy: TRUE (both sides <x, x>).
 cp-vars-false:    vars(Count(2, 3)) edited (value := 3) before return: the frozen dataclass's __dict__: FALSE
                   count 2 ≠ 3 as built; the edit makes the claim's own count 3 (its statement then is 3 = 3).
"""
import copy
import dataclasses
import pickle

from stiefelsym import Count, Rank, admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


@claim("cp-asdict-false", kind="id", sizes=SZ)
def asdict_false(s):
    M = dataclasses.asdict(Rank(s.X @ s.X.T, 1))["matrix"]
    return {"M": M - s.X @ s.X.T + s.In}


@claim("cp-asdict-true", kind="id", sizes=SZ)
def asdict_true(s):
    M = dataclasses.asdict(Rank(s.X @ s.X.T, 1))["matrix"]
    return {"M": M - s.X @ s.X.T}


@claim("cp-pickle-rank", kind="id", sizes=SZ)
def pickle_rank(s):
    try:
        pickle.dumps(Rank(s.X @ s.X.T, 1))
    except Exception:      # noqa: BLE001
        return {"XtX": s.X.T @ s.X - s.Ir}
    return {"XXt": s.X @ s.X.T - s.In}


def _mf_copy(s, k):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    x = s.X @ s.X.T
    G = h.grad(s, x)
    h2 = copy.deepcopy(h)
    object.__setattr__(h2, "value", lambda t, y: t.killing(y, y) / 4)
    return {"euler": s.killing(G, x) - h2(s, x) * k}


@claim("cp-mf-copy-false", kind="id", sizes=SZ)
def mf_copy_false(s):
    return _mf_copy(s, 8)


@claim("cp-mf-copy-true", kind="id", sizes=SZ)
def mf_copy_true(s):
    return _mf_copy(s, 4)


@claim("cp-vars-false", kind="dim", sizes=SZ)
def vars_false(s):
    C = Count(2, 3)
    vars(C)["value"] = 3
    return {"c": C}
