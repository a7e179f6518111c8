# ruff: noqa
"""Graphs that read no point (only A, λ, generic and engine-built letters), whose truth depends on r (q64):
each holds at r = 1 only.  A record computed at the least r and shared with every r whose graph is the same
would pass them at r = 2, 3."""
from stiefelsym import admissible, claim, elementary, twisted

S = admissible(n_max=3)


@claim("q64-sr-trIr", kind="id", sizes=S)
def sr_trir(s):
    """tr I_r = 1 (r = 1 only)."""
    return {"trIr": s.tr(s.Ir) - 1 + 0 * s.tr(s.A)}


@claim("q64-sr-eta", kind="id", sizes=S)
def sr_eta(s):
    """tr(η²) = 0 for η in so(r) (r = 1 only)."""
    return {"tr eta^2": s.tr(s.eta @ s.eta) + 0 * s.tr(s.A)}


@claim("q64-sr-generic-sym", kind="id", sizes=S)
def sr_generic(s):
    """A generic r×r matrix is symmetric (r = 1 only)."""
    G = s.generic("G", "r", "r")
    return {"G-Gt": G - G.T}


@claim("q64-sr-e2", kind="id", sizes=S)
def sr_e2(s):
    """e₂(η) = 0 (r = 1 only: e₂ of a skew matrix is the sum of squares of its entries)."""
    return {"e2": elementary(s, s.eta, 2)[2] + 0 * s.lam}


@claim("q64-sr-operator", kind="id", sizes=S)
def sr_operator(s):
    """𝔸(η) = 0 for the operator on so(r) (r = 1 only)."""
    AA = s.sym_operator()
    return {"AA eta": AA(s.eta)}


@claim("q64-sr-blockC", kind="id", sizes=S)
def sr_block(s):
    """tr C = 0 for the block projector C of size ⌊r/2⌋ (r = 1 only)."""
    C = twisted.block_projector(s, 1)
    return {"trC": s.tr(C) + 0 * s.tr(s.A)}


@claim("q64-sr-last", kind="id", sizes=S)
def sr_last(s):
    """E_r E_rᵀ = I_r (r = 1 only)."""
    E = twisted.last_basis_vector(s)
    return {"ErErt": E @ E.T - s.Ir}


@claim("q64-sr-resolvent-r", kind="id", sizes=S)
def sr_resolvent(s):
    """(λ − A)⁻¹ traced, times tr I_r − 1 (r = 1 only)."""
    return {"x": s.tr(s.resolvent(s.lam)) * (s.tr(s.Ir) - 1)}
