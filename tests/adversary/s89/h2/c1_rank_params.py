"""s89h2: Rank(M, k, generic=False) ("rank k at every point") on matrices that read no coordinate of the
point but hold parameters, and derivatives of functions that close over the claim's own point.
 rk-generic (FALSE): Rank(G, n, generic=False), G a generic n×n matrix (every G: G = 0 has rank 0).
 rk-A (FALSE): Rank(A, n, generic=False) (A = diag(a) is singular where some aᵢ = 0; A is not assumed invertible
    in the standard realization).
 rk-lam (FALSE): Rank(λ I_n, n, generic=False) (λ = 0).
 rk-fresh (FALSE): Rank(F, n, generic=False), F = s.fresh('n', 'n').
 rk-generic-gen (TRUE): Rank(G, n) generic rank n.
 rk-X (TRUE): Rank(X, r, generic=False) (X has orthonormal columns).
 d-outer-true (TRUE): along Ẋ = P, Ṗ = −XPᵀP (H = ½tr PᵀP), d/dt tr(Xᵀ P₀) = tr(PᵀP₀) = tr PᵀP at the point,
    P₀ = s.P captured from the claim's scene (held fixed).
 d-outer-false (FALSE): the same derivative = 0 (what a derivative that moved P₀ too would give:
    tr PᵀP + tr(Xᵀ(−XPᵀP)) = 0 on T*V).
"""
from stiefelsym import Rank, admissible, claim
ANY = admissible(n_max=3)
N2 = admissible(n_max=3, n_min=2)

@claim("rk-generic", kind="dim", sizes=ANY)
def a(s):
    """FALSE: a generic G has rank n at every point (every G)."""
    return {"rank": Rank(s.generic("G", "n", "n"), s.n, generic=False)}

@claim("rk-A", kind="dim", sizes=ANY)
def b(s):
    """FALSE: A has rank n at every point (every a)."""
    return {"rank": Rank(s.A, s.n, generic=False)}

@claim("rk-lam", kind="dim", sizes=ANY)
def c(s):
    """FALSE: λI has rank n for every λ."""
    return {"rank": Rank(s.lam * s.In, s.n, generic=False)}

@claim("rk-fresh", kind="dim", sizes=ANY)
def d(s):
    """FALSE: a fresh F has rank n at every point."""
    return {"rank": Rank(s.fresh("n", "n"), s.n, generic=False)}

@claim("rk-generic-gen", kind="dim", sizes=ANY)
def e(s):
    """TRUE: generic rank of G is n."""
    return {"rank": Rank(s.generic("G", "n", "n"), s.n)}

@claim("rk-X", kind="dim", sizes=ANY)
def f(s):
    """TRUE: X has rank r at every point."""
    return {"rank": Rank(s.X, s.r, generic=False)}

def H(t):
    return t.tr(t.P.T @ t.P) / 2

@claim("d-outer-true", kind="id", sizes=ANY)
def g(s):
    """TRUE: d/dt tr(Xᵀ P₀) = tr PᵀP along the Euclidean flow, P₀ = the claim's P, held fixed."""
    P0 = s.P
    return {"r": s.d(lambda t: t.tr(t.X.T @ P0), s.dirac_flow(H)) - s.tr(s.P.T @ s.P)}

@claim("d-outer-false", kind="id", sizes=N2)
def h(s):
    """FALSE (n ≥ 2): the same derivative = 0."""
    P0 = s.P
    return {"r": s.d(lambda t: t.tr(t.X.T @ P0), s.dirac_flow(H))}
