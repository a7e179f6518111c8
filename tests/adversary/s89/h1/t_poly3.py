"""s89h1: the same products on the coordinate (Cayley) chart: a coordinate is read (X[0,0] times a zero
matrix), which forbids the equivariant reduction, so the exact products are large.

 s89h1-cay-commute (TRUE): M²ΦM = MΦM² + X[0,0]·0.
 s89h1-cay-commute-twin (FALSE for 2 <= r < n): M²GM = MGM² (+ X[0,0]·0), G = XXᵀ.
 s89h1-cay-inverse (TRUE): M(I − Φ²) = I (+ X[0,0]·0).
"""
from stiefelsym import claim

Z = [(3, 1), (3, 2), (4, 2)]


def M_of(s):
    return (s.In - s.Phi @ s.Phi).inv()


def touch(s):
    return s.X[0, 0] * (s.X @ s.X.T - s.X @ s.X.T)


@claim("s89h1-cay-commute", kind="id", sizes=Z)
def cay_commute(s):
    """M²ΦM = MΦM² (true)."""
    M = M_of(s)
    return {"r": M @ M @ s.Phi @ M - M @ s.Phi @ M @ M + touch(s)}


@claim("s89h1-cay-commute-twin", kind="id", sizes=Z)
def cay_commute_twin(s):
    """M²GM = MGM² (false for 2 <= r < n)."""
    M = M_of(s)
    G = s.X @ s.X.T
    return {"r": M @ M @ G @ M - M @ G @ M @ M + touch(s)}


@claim("s89h1-cay-inverse", kind="id", sizes=Z)
def cay_inverse(s):
    """M(I − Φ²) = I (true)."""
    return {"r": M_of(s) @ (s.In - s.Phi @ s.Phi) - s.In + touch(s)}
