"""Class 4: state from the interpreter's string-hash seed (random per invocation unless PYTHONHASHSEED is set).

hs-flip: XᵀX − I_r (TRUE) when hash("stiefel") is even, XXᵀ − I_n (FALSE at r < n) when odd.  Both traces of one run
agree (the children share the seed), so the run is deterministic inside; two runs with the same --seed differ.
"""
import sys

from stiefelsym import admissible, claim

FLIP = hash("stiefel") & 1
print("HASH", hash("stiefel"), file=sys.stderr)


@claim("hs-flip", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def hs_flip(s):
    if FLIP:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}
