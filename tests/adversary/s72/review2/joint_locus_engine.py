"""s72 review2 (attempt C3): does the dimension-free method itself combine the one-r hypotheses of r = 1 and r = n
(a claim stated at n = r = 1 only, or at r = 1 and r = n)?  False claims: tr(X^T X) - r + 1 = 0; (n - 1)·1 = 0 written
with traces; a true one: (n - r)(r - 1) = 0 at those sizes (true at (1,1), and on r = 1 and r = n)."""
from stiefelsym import claim

ONE = [(1, 1)]


@claim("rw2-jl-one-false", kind="id", paper="No", section="t", sizes=ONE)
def jl_one_false(s):
    """tr(X^T X) - r + 1 = 0 at (1,1): false (it is 1)."""
    return {"s": s.tr(s.X.T @ s.X) - s.tr(s.identity(s.r)) + s.q(1)}


@claim("rw2-jl-xxt", kind="id", paper="No", section="t", sizes=ONE)
def jl_xxt(s):
    """X X^T = I_n at (1,1): true."""
    return {"s": s.X @ s.X.T - s.identity(s.n)}


@claim("rw2-jl-prod-true", kind="id", paper="No", section="t", sizes=ONE)
def jl_prod_true(s):
    """(n - r)(r - 1) = 0 at (1,1): true."""
    return {"s": (s.tr(s.identity(s.n)) - s.tr(s.identity(s.r))) * (s.tr(s.identity(s.r)) - s.q(1))}


@claim("rw2-jl-nm1-false", kind="id", paper="No", section="t", sizes=[(1, 1), (2, 2), (3, 3)])
def jl_nm1_false(s):
    """n - 1 = 0 at (1,1), (2,2), (3,3): false at (2,2), (3,3)."""
    return {"s": s.tr(s.identity(s.n)) - s.q(1)}
