"""Class 6: copying, pickling, hashing and formatting tracer objects (new variants).

* c6-copy-true: copy.copy / copy.deepcopy of X, then XcᵀXc = I_r (TRUE if the copy is X).
* c6-copy-false: deepcopy of P used as X: PᵀP − I_r (FALSE) -- checks a copy does not become another leaf.
* c6-reduce-ex: X.__reduce_ex__(2) / pickle.dumps(s.n): the reduced form, if any, decides a branch (TRUE or
  FALSE residual); a refusal is recorded.
* c6-sizeof-branch: sys.getsizeof(s.n) and len(repr(s.X)) and hash(s.n) parity pick TRUE or FALSE; the two
  traces (and the symbolic/number phases) must agree.
* c6-format: format(s.X, "") / f"{s.Psi!s}" / str(s.r) joined into a Python string whose length picks the branch.
"""
import copy
import pickle
import sys
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


@claim("c6-copy-true", paper="t", kind="id", section="0", sizes=SZ)
def copy_true(s):
    """copy(X)ᵀ deepcopy(X) = I_r: TRUE."""
    a, b = copy.copy(s.X), copy.deepcopy(s.X)
    return {"r": a.T @ b - s.Ir}


@claim("c6-copy-false", paper="t", kind="id", section="0", sizes=SZ)
def copy_false(s):
    """deepcopy(P)ᵀ deepcopy(P) = I_r: FALSE."""
    b = copy.deepcopy(s.P)
    return {"r": b.T @ b - s.Ir}


@claim("c6-reduce-ex", paper="t", kind="id", section="0", sizes=SZ)
def reduce_ex(s):
    """Branch on X.__reduce_ex__(2): TRUE residual if it returns, FALSE if it raises."""
    try:
        s.X.__reduce_ex__(2)
        pickle.dumps(s.n)
        ok = True
    except BaseException:
        ok = False
    if ok:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X @ s.X.T - s.In}


@claim("c6-sizeof-branch", paper="t", kind="id", section="0", sizes=SZ)
def sizeof_branch(s):
    """TRUE or FALSE residual by sys.getsizeof(s.n) + len(repr(s.X)) + hash(s.n) parity."""
    k = sys.getsizeof(s.n) + len(repr(s.X)) + (hash(s.n) & 1)
    if k % 2:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X @ s.X.T - s.In}


@claim("c6-format", paper="t", kind="id", section="0", sizes=SZ)
def fmt(s):
    """TRUE or FALSE residual by the length of format(X) + str(Ψ) + str(r)."""
    text = format(s.X, "") + f"{s.Psi!s}" + str(s.r)
    if len(text) % 2:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X @ s.X.T - s.In}
