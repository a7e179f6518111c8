"""Is any parameter of the scene fixed rather than generic?  Each residual is a scene scalar alone: FALSE
(each is a free parameter) — a `proved`/`checked` would mean the engine fixed it."""
from stiefelsym import claim

SZ = [(3, 2)]


@claim("s75-fp-kappa", kind="id", sizes=SZ)
def fp_kappa(s):
    """κ + 1/2 = 0: FALSE (κ is a parameter of the κ-family)."""
    return {"w": s.kappa + s.q(1, 2)}


@claim("s75-fp-eps", kind="id", sizes=SZ)
def fp_eps(s):
    """ε − 1 = 0: FALSE."""
    return {"w": s.eps - 1}


@claim("s75-fp-eps0", kind="id", sizes=SZ)
def fp_eps0(s):
    """ε = 0: FALSE."""
    return {"w": s.eps}


@claim("s75-fp-kappa0", kind="id", sizes=SZ)
def fp_kappa0(s):
    """κ = 0: FALSE."""
    return {"w": s.kappa}


@claim("s75-fp-scalar-b", kind="id", sizes=SZ)
def fp_scalar_b(s):
    """b₂ − b₁ = 0 for the claim's own scalars: FALSE."""
    return {"w": s.scalar("b_2") - s.scalar("b_1")}
