"""s82 hidden2 (h5), third file: the Cauchy–Binet form of the tangency quadric (cone0) of Theorem Gen_Chasles."""
from __future__ import annotations

from stiefelsym import admissible, claim, det

from _common import L_star
from _common3 import VBV

ALL = admissible(n_max=5)


@claim("h5-chasles-cauchy-binet", paper=("Gen_Chasles", "tangency", "cone0", "VV", "2r-integrals"), kind="geo",
       section="8", sizes=ALL)
def chasles_cauchy_binet(s):
    """(cone0) for the 2r-plane Σ̄ spanned by the columns of 𝒱 = [[X, P], [0, I_r]] and the cone Q̄(λ),
    B = diag(R, I_r), R = (λ − A)⁻¹: Σ_I |B|_I^I G_I² = det(𝒱ᵀB𝒱) (Cauchy–Binet), and this is det 𝓛*(λ) (so the
    tangency of Theorem Gen_Chasles is 𝓘_{2r}(λ) = a(λ)det 𝓛*(λ) = 0).  Hand: 𝓛* = [[0, −I], [I, 0]]·M with
    M = [[I + PᵀRP, PᵀRX], [XᵀRP, XᵀRX]], and M is 𝒱ᵀB𝒱 = [[XᵀRX, XᵀRP], [PᵀRX, I + PᵀRP]] with both block
    orders swapped (same determinant); det [[0, −I], [I, 0]] = 1.  Holds off T*V too (indep2_output.txt)."""
    return {"det L* - det(V^T B V)": det(s, L_star(s, s.lam)) - det(s, VBV(s))}
