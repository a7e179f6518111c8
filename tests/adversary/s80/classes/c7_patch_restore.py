"""Class 7 (engine privileges): an engine function replaced by claim code for the duration of the claim's own
calls and put back before the claim returns, so that the fingerprint of the engine (compared after loading and
before every evaluation) sees nothing.

p7-false: h = linear(a) with the stateful covector a of c4_calls_after_check.py (odd calls 0, even calls Ψ);
   residuals h(Ψ) and ∇h − Ψ as plain checks.  For one function a they say a = Ψ and <Ψ, Ψ> = 0: FALSE
   (<Ψ, Ψ> = ½|Ψ|² > 0 at a generic point, r = 2).  The one-function hold (_same_call) is switched off
   while the calls are made.
p7-control: the same without the patch: must be refused (error).
p7-seal: ir.seal's state cleared by claim code, then an engine step registered (primitive): refused or harmless?
"""
import sys

from stiefelsym import admissible, claim
from stiefelsym.brackets import linear

SZ = admissible(n_max=3, n_min=2, r_min=2)
STATE = [0]


def a(t):
    STATE[0] += 1
    return t.Psi if STATE[0] % 2 == 0 else t.Psi - t.Psi


def _calls(s):
    h = linear(a)
    v = h.value(s, s.Psi)
    g = h.gradient(s, s.Psi)
    return {"h": v, "grad": g - s.Psi}


@claim("p7-false", kind="id", sizes=SZ)
def p7_false(s):
    """FALSE (see the module docstring)."""
    STATE[0] = 0
    T = sys.modules["stiefelsym.ir.trace"]
    saved = T._same_call
    T._same_call = lambda *a_, **k_: None
    try:
        return _calls(s)
    finally:
        T._same_call = saved


@claim("p7-control", kind="id", sizes=SZ)
def p7_control(s):
    """FALSE, without the patch (refused)."""
    STATE[0] = 0
    return _calls(s)


@claim("p7-seal", kind="id", sizes=SZ)
def p7_seal(s):
    """FALSE XXᵀ = I_n times an engine step registered after clearing the seal's state."""
    seal = sys.modules["stiefelsym.ir.seal"]
    saved = dict(seal._STATE)
    seal._STATE.clear()
    try:
        import stiefelsym.ir as ir
        zero = ir.primitive("p7_zero")(lambda x: x * 0) if hasattr(ir, "primitive") else None
        R = s.X @ s.X.T - s.In
        return {"r": zero(R) if zero else R}
    finally:
        seal._STATE.update(saved)
