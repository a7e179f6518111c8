"""s89h1: larger exact products (the content step of exact products applies above 2e6 term products).

M = (I − Φ²)⁻¹ (I − Φ² = I + ΦΦᵀ: invertible at every point).
 s89h1-big-cube (TRUE): M³(I − Φ²)³ = I_n.
 s89h1-big-commute (TRUE): M²ΦM = MΦM² (Φ commutes with M).
 s89h1-big-commute-twin (FALSE for 2 <= r < n, e.g. (4,2), (4,3); TRUE at r = 1 and r = n): M²GM = MGM², G = XXᵀ.
 s89h1-big-cube-twin (FALSE): M³(I − Φ²)³ = I_n + ΦΦᵀΦΦᵀ·0 + G − G² ... stated as M³(I − Φ²)² = I_n (false: it is M).
"""
from stiefelsym import claim

Z = [(3, 2), (4, 2), (4, 3)]


def M_of(s):
    return (s.In - s.Phi @ s.Phi).inv()


@claim("s89h1-big-cube", kind="id", sizes=Z)
def big_cube(s):
    """M³(I − Φ²)³ = I (true)."""
    M = M_of(s)
    N = s.In - s.Phi @ s.Phi
    return {"r": M @ M @ M @ N @ N @ N - s.In}


@claim("s89h1-big-cube-twin", kind="id", sizes=Z)
def big_cube_twin(s):
    """M³(I − Φ²)² = I (false)."""
    M = M_of(s)
    N = s.In - s.Phi @ s.Phi
    return {"r": M @ M @ M @ N @ N - s.In}


@claim("s89h1-big-commute", kind="id", sizes=Z)
def big_commute(s):
    """M²ΦM = MΦM² (true)."""
    M = M_of(s)
    return {"r": M @ M @ s.Phi @ M - M @ s.Phi @ M @ M}


@claim("s89h1-big-commute-twin", kind="id", sizes=Z)
def big_commute_twin(s):
    """M²GM = MGM², G = XXᵀ (false for 2 <= r < n)."""
    M = M_of(s)
    G = s.X @ s.X.T
    return {"r": M @ M @ G @ M - M @ G @ M @ M}
