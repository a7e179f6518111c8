"""Resolvents at two spectral parameters that agree on T*V but not as expressions: μ₁ = tr(XᵀX) and μ₂ = r
(μ₁ = μ₂ on T*V).  A rule R(μ₁)R(μ₂) = (R(μ₁) − R(μ₂))/(μ₂ − μ₁) would divide by 0 on T*V.  Docstrings state the
truth (at r where r is not an eigenvalue of A: A is generic)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


@claim("s75-rp-square-zero", kind="id", sizes=SZ)
def rp_square_zero(s):
    """R(tr XᵀX)·R(r) = 0: FALSE (it is R(r)², invertible)."""
    R1 = s.resolvent(s.tr(s.X.T @ s.X))
    R2 = s.resolvent(s.tr(s.Ir))
    return {"w": R1 @ R2}


@claim("s75-rp-difference", kind="id", sizes=SZ)
def rp_difference(s):
    """R(tr XᵀX) − R(r) = 0: TRUE (μ₁ = μ₂ on T*V)."""
    return {"w": s.resolvent(s.tr(s.X.T @ s.X)) - s.resolvent(s.tr(s.Ir))}


@claim("s75-rp-two-lambdas", kind="id", sizes=SZ)
def rp_two_lambdas(s):
    """R(λ)R(κ)(κ − λ) = R(λ) − R(κ): TRUE (the resolvent identity; κ − λ as a factor, no division)."""
    Rl, Rk = s.resolvent(s.lam), s.resolvent(s.kappa)
    return {"w": Rl @ Rk * (s.kappa - s.lam) - Rl + Rk}


@claim("s75-rp-two-lambdas-false", kind="id", sizes=SZ)
def rp_two_lambdas_false(s):
    """R(λ)R(κ)(λ − κ) = R(λ) − R(κ): FALSE (sign)."""
    Rl, Rk = s.resolvent(s.lam), s.resolvent(s.kappa)
    return {"w": Rl @ Rk * (s.lam - s.kappa) - Rl + Rk}


@claim("s75-rp-same-lambda-twice", kind="id", sizes=SZ)
def rp_same_twice(s):
    """R(λ)·R(λ + κ − κ) = R(λ)²... stated as R(λ)R(λ + κ − κ) = 0: FALSE."""
    return {"w": s.resolvent(s.lam) @ s.resolvent(s.lam + s.kappa - s.kappa)}
