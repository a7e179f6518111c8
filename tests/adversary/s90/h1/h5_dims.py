"""h5: ranks and dimension counts, own formulations, with false twins."""
from stiefelsym import Rank, admissible, block, claim
from stiefelsym.bases import matrix_of, so_basis

SZ = admissible(n_max=4)
SZ2 = admissible(n_max=4, n_min=2)


def dimV(n, r):
    return n * r - r * (r + 1) // 2


def ddim(n, r):
    d = dimV(n, r) - (n - r) * (n - r - 1) // 2
    if n > 2 * r:
        d += (n - 2 * r) * (n - 2 * r - 1) // 2
    return d


@claim("h5-constraint-jacobian", paper=("cond_XP", "scalar"), kind="dim", sizes=SZ)
def cjac(s):
    """The Jacobian of (XᵀX, XᵀP + PᵀX) (upper triangles) has rank r(r+1) on T*V."""
    r = int(s.r)
    J = s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X], symmetric=True)
    return {"rank": Rank(s.mat(J), r * (r + 1))}


@claim("h5-constraint-jacobian-TWIN", paper=("cond_XP", "scalar"), kind="dim", sizes=SZ)
def cjac_twin(s):
    """(false twin) rank 2r²."""
    r = int(s.r)
    J = s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X], symmetric=True)
    return {"rank": Rank(s.mat(J), 2 * r * r)}


@claim("h5-phi-jacobian-rank", paper=("ddim", "momentum_map"), kind="dim", sizes=SZ2)
def phijac(s):
    """The generic rank of dΦ on T*V is 2dim V − ddim (restricted to T*V: with the constraint rows)."""
    n, r = int(s.n), int(s.r)
    J = s.jacobian(lambda t: [t.Phi]) + s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X], symmetric=True)
    return {"rank": Rank(s.mat(J), 2 * dimV(n, r) - ddim(n, r) + r * (r + 1))}


@claim("h5-phi-jacobian-rank-TWIN", paper=("ddim", "momentum_map"), kind="dim", sizes=SZ2)
def phijac_twin(s):
    """(false twin) generic rank of dΦ on T*V is dim V."""
    n, r = int(s.n), int(s.r)
    J = s.jacobian(lambda t: [t.Phi]) + s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X], symmetric=True)
    return {"rank": Rank(s.mat(J), dimV(n, r) + r * (r + 1))}


@claim("h5-orbit-dimension", paper=("ddim", "left_action"), kind="dim", sizes=SZ2)
def orbit(s):
    """ξ ↦ (ξX, ξP) on so(n) has generic rank 2dim V − ddim (dimension of a generic SO(n)-orbit in T*V)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: block([[xi @ s.X], [xi @ s.P]]), so_basis(s, "n"))
    return {"rank": Rank(M, 2 * dimV(n, r) - ddim(n, r))}


@claim("h5-orbit-dimension-TWIN", paper=("ddim", "left_action"), kind="dim", sizes=SZ2)
def orbit_twin(s):
    """(false twin) rank dim V + ddim − dim V... i.e. ddim."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: block([[xi @ s.X], [xi @ s.P]]), so_basis(s, "n"))
    return {"rank": Rank(M, ddim(n, r))}
