"""Class 7: the Inverse statement's refusal of a non-constant divisor (Trace._divisor, route BA) switched off
by claim code, (a) for good (never restored), (b) restored by a later engine call the claim wraps.

d7-false: Inverse(x ↦ tr(PᵀP)·x, y ↦ y / tr(PᵀP)) on Sym(r): FALSE, at the points of T*V with P = 0
   (in T*V: XᵀP + PᵀX = 0 holds) op is the zero map, not invertible.  Both identities hold as rational
   functions, which is why the engine refuses a non-constant divisor.
d7-control: the same without the patch: refused.
"""
import sys

from stiefelsym import Inverse, admissible, claim

SZ = admissible(n_max=3, n_min=2)


def _op(t, x):
    return x * t.tr(t.P.T @ t.P)


def _inv(t, y):
    return y / t.tr(t.P.T @ t.P)


@claim("d7-false", kind="id", sizes=SZ)
def d7_false(s):
    """FALSE (see the module docstring)."""
    T = sys.modules["stiefelsym.ir.trace"]
    T.Trace._divisor = lambda self, out, stop: ""
    T.Trace._reads_elements = lambda self, out, stop: False
    return {"inv": Inverse(_op, _inv, on="Sym(r)")}


@claim("d7-control", kind="id", sizes=SZ)
def d7_control(s):
    """FALSE, without the patch."""
    return {"inv": Inverse(_op, _inv, on="Sym(r)")}
