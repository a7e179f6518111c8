"""Negative indices and a reversed slice: X[-1, 0] (the entry (n,1), TRUE statement "X[-1,0] - X[2,0] = 0" at n = 3) prints X₀₁; X[::-1, :] prints "X[1..end step -1, :]"."""
from stiefelsym import claim

@claim("p-neg", kind="id", sizes=[(3, 2)])
def p_neg(s):
    return {"a": s.X[-1, 0] - s.X[2, 0], "c": s.X[::-1, :][::-1, :] - s.X}
