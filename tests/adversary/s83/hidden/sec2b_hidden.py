"""h3 hidden statements, §2: the rank of the momentum map's value Φ = PXᵀ − XPᵀ."""
from stiefelsym import Rank, admissible, claim


@claim("h3-phi-rank", kind="dim", section="2",
       sizes=admissible(5, n_min=2, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def phi_rank(s):
    """Φ = Σ p_i ∧ e_i (momentum_map) maps ℝⁿ into span(X, P), of dimension 2r at a generic point when n ≥ 2r, and
    Φ restricted there is nondegenerate (in the basis (X, P₁ = (I − XXᵀ)P) with K = XᵀP, Φ = [[K − K... ]]: on the
    generic point X = (E₁..E_r), P = (0; Z) it is [[0, −Zᵀ], [Z, 0]], rank 2r).  So rank Φ = 2r generically."""
    return {"rank Phi": Rank(s.Phi, 2 * int(s.r))}


@claim("h3-phi-rank-twin", kind="dim", section="2",
       sizes=admissible(5, n_min=2, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def phi_rank_twin(s):
    """FALSE twin: rank 2r at EVERY point (false at P = 0, a point of T*V)."""
    return {"rank Phi": Rank(s.Phi, 2 * int(s.r), generic=False)}


@claim("h3-phi-rank-twin-down", kind="dim", section="2",
       sizes=admissible(5, n_min=2, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def phi_rank_twin_down(s):
    """FALSE twin: rank 2r − 1 (a skew matrix has even rank)."""
    return {"rank Phi": Rank(s.Phi, 2 * int(s.r) - 1)}
