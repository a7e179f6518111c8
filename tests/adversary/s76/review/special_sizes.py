"""Identities true only at special sizes: r = n - 1 (the normal space is a line), n odd (det of a skew
n x n matrix), r odd; each stated at every size up to n = 5 so that the others must fail."""
from stiefelsym import admissible, claim, det


@claim("s76-rank-one-normal", kind="id", sizes=admissible(n_max=5, where=lambda n, r: r == n - 1,
                                                           condition="r = n - 1"))
def rank_one_normal(s):
    """At r = n − 1, N = I − XXᵀ has rank 1: N G N = tr(N G) N for every G (true)."""
    G = s.generic("G", "n", "n")
    N = s.In - s.X @ s.X.T
    return {"NGN": N @ G @ N - s.tr(N @ G) * N}


@claim("s76-rank-one-normal-all", kind="id", sizes=admissible(n_max=4))
def rank_one_normal_all(s):
    """The same stated at every size: FALSE where r < n − 1 (true at r = n − 1 and r = n, N = 0)."""
    G = s.generic("G", "n", "n")
    N = s.In - s.X @ s.X.T
    return {"NGN": N @ G @ N - s.tr(N @ G) * N}


@claim("s76-det-phi", kind="id", sizes=admissible(n_max=5))
def det_phi(s):
    """det Φ = 0: true for n odd, and for n even when 2r < n (rank Φ <= 2r); FALSE at (2,1), (2,2), (4,2), (4,3), (4,4)."""
    return {"det": det(s, s.Phi)}


@claim("s76-det-psi", kind="id", sizes=admissible(n_max=5))
def det_psi(s):
    """det Ψ = 0: true for r odd, FALSE for r even (r = 2: Ψ = 2XᵀP, a nonzero 2 x 2 skew matrix)."""
    return {"det": det(s, s.Psi)}


@claim("s76-pf-psi", kind="id", sizes=admissible(n_max=5, where=lambda n, r: r == 2, condition="r = 2"))
def pf_psi(s):
    """At r = 2, det Ψ = Ψ₁₂² (true)."""
    return {"pf": det(s, s.Psi) - s.Psi[0, 1] * s.Psi[0, 1]}
