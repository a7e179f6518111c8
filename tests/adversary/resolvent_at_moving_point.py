"""Gradients and brackets of a trace form with a resolvent at a spectral parameter that moves with the point,
μ = tr(PᵀP) + λ (dR/dμ = −R², so the P-gradient of tr(XᵀR(μ)X) is −2 tr(XᵀR(μ)²X) P).  The derivative
passes write these as graph nodes; the two false statements below drop the μ-dependence, the third is the
true gradient."""
from stiefelsym import admissible, claim


def H(t):
    mu = t.tr(t.P.T @ t.P) + t.lam
    return t.tr(t.X.T @ t.resolvent(mu) @ t.X)


@claim("adv-moving-mu-gradient", kind="id", sizes=admissible(n_max=3))
def moving_mu_gradient(s):
    """False: the P-gradient of tr(XᵀR(μ)X) is 0 (as if μ did not move)."""
    _, HP = s.gradient(H)
    return {"H_P": HP}


@claim("adv-moving-mu-bracket", kind="pb", sizes=admissible(n_max=3))
def moving_mu_bracket(s):
    """False: {tr(XᵀR(μ)X), tr(XᵀAX)} = 0."""
    return {"bracket": s.bracket(H, lambda t: t.tr(t.X.T @ t.A @ t.X))}


@claim("adv-moving-mu-gradient-true", kind="id", sizes=admissible(n_max=3))
def moving_mu_gradient_true(s):
    """True: the P-gradient of tr(XᵀR(μ)X) is −2 tr(XᵀR(μ)²X) P."""
    _, HP = s.gradient(H)
    R = s.resolvent(s.tr(s.P.T @ s.P) + s.lam)
    return {"H_P + 2 tr(X^T R^2 X) P": HP + 2 * s.tr(s.X.T @ R @ R @ s.X) * s.P}
