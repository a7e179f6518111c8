"""s89h1: rank, count and does-not-vanish claims at n = 5, 6 (auto runs the dimension-free proof first there).

 s89h1-count-so-n (TRUE at n = 5, FALSE at n = 6): Count(n(n-1)/2, 10).
 s89h1-rank-phi (TRUE at (5,1), (5,2), (6,2); FALSE at (5,5) where rank Φ = rank Ψ = 4 and at (6,6) where it is 6):
     rank Φ = min(2r, n) ... stated as Rank(Φ, 2r) (2r ≤ n) i.e. 2, 4, 4; at (5,5): 10 ≠ 4; at (6,6): 12 ≠ 6.
 s89h1-rank-phi-exact (TRUE at all): rank Φ = 2r if 2r <= n, else n if n even, n - 1 if n odd (r = n: rank Ψ).
     (At r < n < 2r: Φ restricted ... for (5,4): min(2r, n) = 5 but Φ skew so even: 4.)
 s89h1-nonzero-psi (TRUE for r >= 2, FALSE at r = 1): Ψ does not vanish identically.
 s89h1-nonzero-casimir-zero (FALSE): expect nonzero of ⟨Φ,Φ⟩ − tr PᵀP − ½⟨Ψ,Ψ⟩ (identically 0).
"""
from stiefelsym import claim, Rank, Count

Z = [(5, 1), (5, 2), (5, 4), (5, 5), (6, 1), (6, 2), (6, 6)]


@claim("s89h1-count-so-n", kind="dim", sizes=[(5, 1), (5, 2), (6, 1), (6, 2)])
def count_so_n(s):
    """dim so(n) = 10 (true at n = 5 only)."""
    n = int(s.n)
    return {"dim": Count(n * (n - 1) // 2, 10)}


@claim("s89h1-rank-phi", kind="dim", sizes=Z)
def rank_phi(s):
    """rank Φ = 2r (true iff 2r <= n)."""
    return {"rank": Rank(s.Phi, 2 * int(s.r))}


@claim("s89h1-rank-phi-exact", kind="dim", sizes=Z)
def rank_phi_exact(s):
    """rank Φ = 2r for 2r <= n, else the largest even number <= n (true)."""
    n, r = int(s.n), int(s.r)
    k = 2 * r if 2 * r <= n else n - (n % 2)
    return {"rank": Rank(s.Phi, k)}


@claim("s89h1-nonzero-psi", kind="not", expect="nonzero", sizes=Z)
def nonzero_psi(s):
    """Ψ does not vanish (true for r >= 2; false at r = 1)."""
    return {"psi": s.Psi}


@claim("s89h1-nonzero-casimir-zero", kind="not", expect="nonzero", sizes=Z)
def nonzero_casimir(s):
    """⟨Φ,Φ⟩ − tr PᵀP − ½⟨Ψ,Ψ⟩ does not vanish (false: it is identically 0)."""
    return {"c": s.killing(s.Phi, s.Phi) - s.tr(s.P.T @ s.P) - s.killing(s.Psi, s.Psi) / 2}
