"""Order of claims for the shared hard-momenta state: a claim reading P first, then claims reading none (same
process, same sizes).  Truth in each docstring."""
from stiefelsym import admissible, claim


@claim("r2-o-reads-p", kind="id", sizes=admissible(n_max=3))
def reads_p(s):
    """Ψ + Ψᵀ = 0: TRUE; reads P."""
    return {"w": s.Psi + s.Psi.T}


@claim("r2-o-x-true", kind="id", sizes=admissible(n_max=3))
def x_true(s):
    """XᵀX = I_r: TRUE; reads no P."""
    return {"w": s.X.T @ s.X - s.Ir}


@claim("r2-o-x-false-tiny", kind="id", sizes=admissible(n_max=3))
def x_false_tiny(s):
    """XᵀX − I_r + 2⁻⁶⁰ XᵀAX = 0: FALSE; reads no P (a residual float64 cannot see next to I_r)."""
    return {"w": s.X.T @ s.X - s.Ir + s.X.T @ s.A @ s.X * s.q(1, 2**60)}


@claim("r2-o-reads-p-again", kind="id", sizes=admissible(n_max=3))
def reads_p_again(s):
    """tr Φ = 0: TRUE; reads P."""
    return {"w": s.tr(s.Phi)}
