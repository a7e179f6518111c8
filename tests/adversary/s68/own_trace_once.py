# ruff: noqa
"""Stop 68's own attempt: a claims file asks the engine to trace its claim once (ir.trace_once, meant for the
catalog's mutants), and the claim says one thing on its first trace and another on the next."""
from stiefelsym import admissible, claim
from stiefelsym import ir

_calls = [0]


@claim("ot-flip", kind="id", sizes=admissible(n_max=3))
def flip(s):
    """XᵀX = Iᵣ on the first trace; XᵀX = 2Iᵣ (false) on every later one."""
    _calls[0] += 1
    k = 1 if _calls[0] == 1 else 2
    return {"XtX": s.X.T @ s.X - k * s.Ir}


ir.trace_once(flip)
ir.trace_once(flip.claim.func)
