"""Class 5 (the error model of a constant / a bound): the degree bound of a generic rank's minors.

A generic rank below full size, beyond the exact method's symbolic function-field rank (5 s), is bounded from
above at random points of prime fields with Schwartz-Zippel, D/p per point, D the structural degree bound of the
(k+1)-minors.  The structural bound can be inflated by a factor that is identically 0 on T*V:
z = tr(XᵀX) − tr(I_r) (0 on V(n, r)), squared 64 times: the marker says degree 2^65·deg, the value is 0.

c5-deg-true:  M = U V + z·(U V), U = U1·U2 a generic 12×6 times 6×6, V = V2·V1 likewise (untyped spaces of the claim's own):
  rank M = rank(U V) = 6 generically (U, V generic of full rank 6).  TRUE.  Rank(M, 6).
c5-deg-false: the same, Rank(M, 7).  FALSE (rank 6 < 7).
c5-deg-plain-true: U V without z, Rank 6: TRUE (control: the same matrix without the inflated marker).
c5-deg-small-true / -false: a small matrix (2x2 rank 1 of generics) with z: TRUE rank 1 / FALSE rank 2.
"""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=3, n_min=2)
M_, K_ = 12, 6


def _uv(s, m=M_, k=K_):
    U = s.general_params("U", m, k, ("?", "?"))
    V = s.general_params("V", k, m, ("?", "?"))
    if m > 99:     # entries of degree 4: U·(U2) and (V2)·V, so that the function-field rank takes long
        U = U @ s.general_params("U2", k, k, ("?", "?"))
        V = s.general_params("V2", k, k, ("?", "?")) @ V
    return U @ V


def _z(s, times=64):
    z = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    for _ in range(times):
        z = z * z
    return z


@claim("c5-deg-true", kind="dim", sizes=SZ)
def c5_deg_true(s):
    """rank(UV + z·UV) = 4, z = 0 on V(n, r)."""
    M = _uv(s)
    return {"rank": Rank(M + _z(s) * M, K_)}


@claim("c5-deg-false", kind="dim", sizes=SZ)
def c5_deg_false(s):
    """rank(UV + z·UV) = 5 (false: 4)."""
    M = _uv(s)
    return {"rank": Rank(M + _z(s) * M, K_ + 1)}


@claim("c5-deg-plain-true", kind="dim", sizes=SZ)
def c5_deg_plain_true(s):
    """rank(UV) = 4."""
    return {"rank": Rank(_uv(s), K_)}


@claim("c5-deg-small-true", kind="dim", sizes=SZ)
def c5_deg_small_true(s):
    """rank(uvᵀ + z·uvᵀ) = 1 for 3-vectors u, v."""
    M = _uv(s, 3, 1)
    return {"rank": Rank(M + _z(s) * M, 1)}


@claim("c5-deg-small-false", kind="dim", sizes=SZ)
def c5_deg_small_false(s):
    """rank(uvᵀ + z·uvᵀ) = 2 (false: 1)."""
    M = _uv(s, 3, 1)
    return {"rank": Rank(M + _z(s) * M, 2)}
