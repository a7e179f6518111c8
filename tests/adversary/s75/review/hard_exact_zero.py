"""Residuals that are exactly 0 at a hard case's chosen point but not identically: false claims.
Each docstring states the truth."""
from stiefelsym import admissible, claim


@claim("s75-pole-exact-zero", kind="id", sizes=admissible(n_max=3))
def pole_exact_zero(s):
    """10^12 (λ − a₁) = 1: FALSE (λ is a free parameter); exactly 0 at near-pole's λ = a₁ + 10⁻¹²."""
    a1 = s.a[0]
    return {"w": (s.lam - a1) * s.q(10**12, 1) - 1}


@claim("s75-pole-exact-zero-matrix", kind="id", sizes=admissible(n_max=3))
def pole_exact_zero_matrix(s):
    """(10^12 (λ − a₁) − 1) XᵀX = 0: FALSE; 0 at the near-pole point."""
    a1 = s.a[0]
    c = (s.lam - a1) * s.q(10**12, 1) - 1
    return {"w": s.X.T @ s.X * c}


@claim("s75-pole-resolvent", kind="id", sizes=admissible(n_max=3))
def pole_resolvent(s):
    """(λ − a₁)·R(λ)₁₁ = 1 holds (A diagonal: R₁₁ = 1/(λ − a₁)) - TRUE; and 10^-12 R(λ)₁₁ = 1: FALSE, 0 at near-pole."""
    R = s.resolvent(s.lam)
    return {"w": R[0, 0] * s.q(1, 10**12) - 1}
