"""h11: the generic adjoint orbit in Φ(T*V) (Lemma 2l) as a rank of ad_Φ, and the tori count as a Count."""
from stiefelsym import Count, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

SZ2 = admissible(n_max=4, n_min=2)


def two_l(n, r):
    return n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)


@claim("h11-adphi-rank", paper="2l", kind="dim", sizes=SZ2)
def adphi(s):
    """ξ ↦ [ξ, Φ] on so(n) has generic rank 2l (Lemma 2l)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: comm(xi, s.Phi), so_basis(s, "n"), "skew")
    return {"rank": Rank(M, two_l(n, r))}


@claim("h11-adphi-rank-TWIN", paper="2l", kind="dim", sizes=SZ2)
def adphi_twin(s):
    """(false twin) generic rank n(n−1)/2 − [n/2] at every size."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: comm(xi, s.Phi), so_basis(s, "n"), "skew")
    return {"rank": Rank(M, n * (n - 1) // 2 - n // 2)}


@claim("h11-manakov-tori-count", paper=("man", "bols-jov", "ddim", "2l"), kind="dim",
       sizes=admissible(n_max=4, condition="n >= 2r", where=lambda n, r: n >= 2 * r))
def tori(s):
    """For n ≥ 2r, δ = 2dim V − ddim − l equals r(n − r)."""
    n, r = int(s.n), int(s.r)
    dimV = n * r - r * (r + 1) // 2
    ddim = dimV - (n - r) * (n - r - 1) // 2 + (n - 2 * r) * (n - 2 * r - 1) // 2
    return {"delta": Count(2 * dimV - ddim - two_l(n, r) // 2, r * (n - r))}
