"""s82 hidden (h2): engine probes around the r = 2 / twisted statements (not new paper statements).
Truth by hand (each docstring); the (n, r) where each holds is given by fails_at.

p82-phi-conserved-magnetic-geodesic: at n = 2, e₁∧e₂ = XJXᵀ = det(X)·J is constant, so with Φ_ε = Φ + εXJXᵀ
  conserved (mag-mom-stief) Φ is conserved; for n ≥ 3 it is not (the magnetic torque).  True only at (2, 2).
p82-psi-commutes-J: r = 2, so(2) is abelian: [Ψ, J] = 0 at every n.  True.
p82-psi-commutes-eta: [Ψ, η] = 0 for a generic η ∈ so(r): true for r ≤ 2, false for r ≥ 3.
p82-twisted-F-scalar-multiple: r = 2, η = η₁₂J and ⟨η, J⟩ = η₁₂: the twisted flows for F = η and F = ⟨η, J⟩J agree.
p82-twisted-F-eta-psi12: r = 2, the flow of Ψ₁₂ for ω_F, F = η (a multiple of de₁∧de₂) is still (XJ, PJ).
"""
from stiefelsym import admissible, claim, comm, twisted

from _h82_helpers import H_euclid_neumann, psi12

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


@claim("p82-phi-conserved-magnetic-geodesic", kind="pb", sizes=R2, fails_at=lambda n, r: n >= 3,
       erratum="true at n = 2 only")
def phi_conserved(s):
    """dΦ/dt = 0 along the Euclidean magnetic geodesic flow (true at n = 2 only)."""
    flow = twisted.flow(s, lambda t: t.tr(t.P.T @ t.P) / 2)
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow)}


@claim("p82-psi-commutes-J", kind="id", sizes=R2)
def psi_commutes_J(s):
    """[Ψ, J] = 0 at r = 2."""
    return {"[Psi, J]": comm(s.Psi, twisted.magnetic_matrix(s))}


@claim("p82-psi-commutes-eta", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r >= 3,
       erratum="so(r) is abelian only for r <= 2")
def psi_commutes_eta(s):
    """[Ψ, η] = 0 (true for r ≤ 2 only)."""
    return {"[Psi, eta]": comm(s.Psi, s.eta)}


@claim("p82-twisted-F-scalar-multiple", kind="id", sizes=R2)
def twisted_F_scalar_multiple(s):
    """r = 2: flow for F = η equals flow for F = ⟨η, J⟩J."""
    J = twisted.magnetic_matrix(s)
    f1 = twisted.flow(s, H_euclid_neumann, s.eta)
    f2 = twisted.flow(s, H_euclid_neumann, s.killing(s.eta, J) * J)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("p82-twisted-F-eta-psi12", kind="pb", sizes=R2)
def twisted_F_eta_psi12(s):
    """r = 2: for ω_F with F = η, the flow of Ψ₁₂ is (XJ, PJ)."""
    J = twisted.magnetic_matrix(s)
    f = twisted.flow(s, psi12, s.eta)
    return {"X' - XJ": f["X"] - s.X @ J, "P' - PJ": f["P"] - s.P @ J}
