"""h3 probe of the metric realization's chart (B = A⁻¹ blocks D₁, D₂ diagonal at X₀): a statement that holds
exactly when XᵀA⁻¹X is diagonal, i.e. at the chart's base point only, written through an ℝʳ constant basis
element or an entry."""
from stiefelsym import admissible, claim
from stiefelsym.bases import sym_basis


@claim("h3-metric-gram-symmetric", kind="id", section="3", realization="metric",
       sizes=admissible(5, r_min=2, condition="r >= 2"))
def metric_gram_symmetric(s):
    """Honest: M = XᵀA⁻¹X is symmetric, so tr((E₁₂ − E₂₁)M) = M₂₁ − M₁₂ = 0, and tr((E₁₂+E₂₁)(M − Mᵀ)) = 0."""
    M = s.X.T @ s.Ainv @ s.X
    E = sym_basis(s, "r")[int(s.r)]
    return {"sym": s.tr(E @ (M - M.T)), "entry": M[0, 1] - M[1, 0]}


@claim("h3-metric-gram-offdiag-twin", kind="id", section="3", realization="metric",
       sizes=admissible(5, r_min=2, condition="r >= 2"))
def metric_gram_offdiag_twin(s):
    """FALSE twin: tr((E₁₂ + E₂₁) XᵀA⁻¹X) = 2(XᵀA⁻¹X)₁₂ = 0 (true only where XᵀA⁻¹X is diagonal)."""
    M = s.X.T @ s.Ainv @ s.X
    E = sym_basis(s, "r")[int(s.r)]
    return {"offdiag": s.tr(E @ M)}


@claim("h3-metric-gram-entry-twin", kind="id", section="3", realization="metric",
       sizes=admissible(5, r_min=2, condition="r >= 2"))
def metric_gram_entry_twin(s):
    """FALSE twin: (XᵀA⁻¹X)₁₂ = 0."""
    M = s.X.T @ s.Ainv @ s.X
    return {"offdiag": M[0, 1]}


@claim("h3-metric-gram-commutes-twin", kind="id", section="3", realization="metric",
       sizes=admissible(5, r_min=2, n_min=3, where=lambda n, r: r < n, condition="2 <= r < n"))
def metric_gram_commutes_twin(s):
    """FALSE twin, coordinate-free: XᵀA⁻¹X commutes with XᵀA⁻²X (false in general: at X₀ these are B₁₁ and
    B₁₁² + B₁₂B₂₁; true at r = n where X is orthogonal)."""
    M1 = s.X.T @ s.Ainv @ s.X
    M2 = s.X.T @ s.Ainv @ s.Ainv @ s.X
    return {"comm": M1 @ M2 - M2 @ M1}
