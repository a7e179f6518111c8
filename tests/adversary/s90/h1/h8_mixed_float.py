"""h8: a file with one dim claim and one identity, to see how float treats the dim claim."""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=3)


@claim("h8-dimV-rank", kind="dim", sizes=SZ)
def dimv(s):
    """rank of the constraint Jacobian is r(r+1)."""
    r = int(s.r)
    J = s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X], symmetric=True)
    return {"rank": Rank(s.mat(J), r * (r + 1))}


@claim("h8-trivial", kind="id", sizes=SZ)
def triv(s):
    """XᵀX = I."""
    return {"XtX": s.X.T @ s.X - s.Ir}
