"""Class 4: state across calls (new variants).

* c4-a sets a module global when traced; c4-b returns XᵀX − I_r (TRUE) when the global is set and XXᵀ − I_n
  (FALSE) otherwise: does a claim's graph depend on which other claims of the file were traced before it
  (run order / selection), and what do `check` and `report --check` then say?
* c4-builtins: state parked in `builtins` and in `sys.modules` (a fake module) by c4-a, read by c4-c.
* c4-gen-exhaust: a generator shared by both traces: first trace gets TRUE, second FALSE -> NotDeterministic.
* c4-lambda-default: a function handed to s.d with a mutable default argument that grows each call.
"""
import builtins
import sys
import types
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)
STATE = {"a": 0}


@claim("c4-a", paper="t", kind="id", section="0", sizes=SZ)
def a(s):
    """XᵀX = I_r (TRUE); sets state."""
    STATE["a"] += 1
    builtins._c4_flag = True
    sys.modules["_c4_fake"] = types.ModuleType("_c4_fake")
    return {"r": s.X.T @ s.X - s.Ir}


@claim("c4-b", paper="t", kind="id", section="0", sizes=SZ)
def b(s):
    """TRUE (XᵀX = I_r) if c4-a ran before in this interpreter, else FALSE (XXᵀ = I_n)."""
    if STATE["a"]:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X @ s.X.T - s.In}


@claim("c4-c", paper="t", kind="id", section="0", sizes=SZ)
def c(s):
    """TRUE if builtins/sys.modules carry c4-a's marks, else FALSE."""
    if getattr(builtins, "_c4_flag", False) or "_c4_fake" in sys.modules:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X @ s.X.T - s.In}


_gen = iter([True] + [False] * 100)


@claim("c4-gen-exhaust", paper="t", kind="id", section="0", sizes=SZ)
def gen(s):
    """first trace TRUE residual, later traces FALSE."""
    if next(_gen):
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X @ s.X.T - s.In}


def H(t, acc=[]):  # noqa: B006 - the state across calls is the trick
    acc.append(1)
    return t.tr(t.P.T @ t.P) / 2 * len(acc)


@claim("c4-lambda-default", paper="t", kind="id", section="0", sizes=SZ)
def lam_default(s):
    """d/dt H = 0 along the Dirac flow of H (TRUE for any fixed H), with H scaled by its call count."""
    flow = s.dirac_flow(H)
    return {"dH": s.d(H, flow)}
