"""s89h2 classes 3/4: branches on comparisons of sizes (Dim comparisons are one question to the trace).
Each claim returns a TRUE residual (XᵀX − I_r) on one branch and a FALSE one on the other; the claim is FALSE
at the sizes of the FALSE branch.  A free `proved` (every n, r) or a pass at such a size is a wrong verdict.
 sb-square (FALSE at r = n): if r == n: XXᵀ = 0 (FALSE) else XᵀX = I_r.
 sb-lt (FALSE at r < n): if n > r: XXᵀ = I_n (FALSE) else XᵀX = I_r.
 sb-r2 (FALSE at r >= 2): if r >= 2: XᵀP = 0 (FALSE) else XᵀX = I_r.
 sb-n3 (FALSE at n = 3, r < 3): if n == 3: XXᵀ = I_n else XᵀX = I_r.
 sb-ne (FALSE at r != n): if r != n: XXᵀ = I_n else XᵀX = I_r.
"""
from stiefelsym import admissible, claim
ANY = admissible(n_max=3)
def T_(s): return {"r": s.X.T @ s.X - s.Ir}

@claim("sb-square", kind="id", sizes=ANY)
def a(s):
    """FALSE at r = n."""
    if s.r == s.n:
        return {"r": s.X @ s.X.T}
    return T_(s)

@claim("sb-lt", kind="id", sizes=ANY)
def b(s):
    """FALSE at r < n."""
    if s.n > s.r:
        return {"r": s.X @ s.X.T - s.In}
    return T_(s)

@claim("sb-r2", kind="id", sizes=ANY)
def c(s):
    """FALSE at r >= 2."""
    if s.r >= 2:
        return {"r": s.X.T @ s.P}
    return T_(s)

@claim("sb-n3", kind="id", sizes=ANY)
def d(s):
    """FALSE at n = 3, r < 3."""
    if s.n == 3:
        return {"r": s.X @ s.X.T - s.In}
    return T_(s)

@claim("sb-ne", kind="id", sizes=ANY)
def e(s):
    """FALSE at r != n."""
    if s.r != s.n:
        return {"r": s.X @ s.X.T - s.In}
    return T_(s)
