"""s82 hidden (h2), statement 13: (mag-nor) of Appendix 1 in matrix form, and its twin.

13 (App.1 mag-nor) columns ε Φe₂, −ε Φe₁ = εΦXJᵀ (= εẊJᵀ, as εPJᵀ = εẊJᵀ in (mag-euk)); the diagonal terms
   −ε(e₁, Φe₂), +ε(e₂, Φe₁) are equal (Φ skew) and (e₁, Φe₂) = (XᵀΦX)₁₂ = Ψ₁₂ (XᵀΦX = XᵀP − PᵀX = Ψ):
   Ẋ = ΦX, Ṗ = ΦP − AX + X(XᵀAX − εΨ₁₂I) + εΦXJᵀ — the coefficient of Ψ₁₂ is ε here, ε/2 in (mag-euk)
   (h82-mag-euk-matrix-form).  Twin: ½εΨ₁₂ (the Euclidean coefficient).  numpy: indep2.py.in.
"""
from stiefelsym import admissible, claim, twisted

from _h82_helpers import psi12

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def H_normal_neumann(t):
    """(N0_XP2) Hamiltonian: ½⟨Φ, Φ⟩ + ½tr XᵀAX."""
    return t.killing(t.Phi, t.Phi) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def _mag_nor(s, c):
    J = twisted.magnetic_matrix(s)
    X, P, A, Ph = s.X, s.P, s.A, s.Phi
    f = twisted.flow(s, H_normal_neumann)
    Lam = X.T @ A @ X - c * s.eps * psi12(s) * s.Ir
    return {"X' - Phi X": f["X"] - Ph @ X,
            "P' - matrix form": f["P"] - (Ph @ P - A @ X + X @ Lam + s.eps * (Ph @ X @ J.T))}


@claim("h82-mag-nor-matrix-form", paper=("mag-nor", "twisted"), kind="id", sizes=R2)
def mag_nor_matrix_form(s):
    """(mag-nor): Ẋ = ΦX, Ṗ = ΦP − AX + X(XᵀAX − εΨ₁₂I) + εΦXJᵀ."""
    return _mag_nor(s, 1)


@claim("n82-mag-nor-matrix-form", paper=("mag-nor", "twisted"), kind="id", sizes=R2,
       fails_at=lambda n, r: True, erratum="twin: eps/2 Psi12")
def mag_nor_matrix_form_twin(s):
    """Twin: ½εΨ₁₂."""
    return _mag_nor(s, s.q(1, 2))
