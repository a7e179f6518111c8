"""h1 (stop 84), the seal: a claim whose own body replaces an engine method while it is traced and puts it back
before it returns (plain Python: Tracer.__add__ = Tracer.__sub__; no memory writes).  The engine is compared with
its fingerprint after the import and before each evaluation; a change made and undone inside the claim's run is
between those comparisons.

h1-seal-swap-add     x = P + P, traced while + is −: FALSE (2P ≠ 0).  Must be `fails` or `error`, never proved.
h1-seal-swap-ctrl    x = XᵀX − I_r with the same swap around it (no + used): TRUE (control).
"""
from stiefelsym import admissible, claim
from stiefelsym.ir.trace import Tracer

SZ = admissible(n_max=3, n_min=2)


@claim("h1-seal-swap-add", kind="id", sizes=SZ)
def swap_add(s):
    orig = Tracer.__dict__["__add__"]
    Tracer.__add__ = Tracer.__dict__["__sub__"]
    try:
        x = s.P + s.P
    finally:
        Tracer.__add__ = orig
    return {"x": x}


@claim("h1-seal-swap-ctrl", kind="id", sizes=SZ)
def swap_ctrl(s):
    orig = Tracer.__dict__["__add__"]
    Tracer.__add__ = Tracer.__dict__["__sub__"]
    try:
        x = s.X.T @ s.X - s.Ir
    finally:
        Tracer.__add__ = orig
    return {"x": x}
