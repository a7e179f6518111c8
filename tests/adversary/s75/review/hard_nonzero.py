"""Statements that something does not vanish, whose residual is exactly 0 at a hard case's chosen point.
All TRUE (the residual is not identically 0 on T*V)."""
from stiefelsym import admissible, claim


@claim("s75-nz-pole", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def nz_pole(s):
    """10^12 (λ − a₁) − 1 does not vanish identically: TRUE; 0 at near-pole's λ = a₁ + 10⁻¹²."""
    return {"w": (s.lam - s.a[0]) * s.q(10**12, 1) - 1}


@claim("s75-nz-pole-resolvent", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def nz_pole_resolvent(s):
    """10⁻¹² R(λ)₁₁ − 1 does not vanish identically: TRUE; 0 at near-pole."""
    return {"w": s.resolvent(s.lam)[0, 0] * s.q(1, 10**12) - 1}


@claim("s75-nz-momenta", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def nz_momenta(s):
    """tr(PᵀP) · 10⁻¹² ... − tr(PᵀP)/10^12 + (Φ scaled) : the residual 10^-12 tr(PᵀP)... TRUE nonzero."""
    return {"w": s.tr(s.P.T @ s.P) * s.q(1, 10**12)}
