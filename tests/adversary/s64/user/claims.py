# ruff: noqa
"""True statements of Sections 5, 7 and Appendices 1-2 of Fedorov-Jovanovic, restated (s64)."""
from stiefelsym import admissible, claim, comm, twisted, systems
from _common import (H_kappa, H_normal, H_eucl, no_flow, wedge, L_hat, L_eps, cross_col,
                     coupled_H, double_tangent)


@claim("u64-prep-kappa", paper="prep", kind="id", sizes=admissible(n_max=4))
def prep_along_printed_No(s):
    """(prep) along the printed flow (No) for a generic κ: d(XXᵀ)/dt = [Φ, XXᵀ] and dΦ/dt = [XXᵀ, A]."""
    fl = no_flow(s)
    XX = s.X @ s.X.T
    return {"dXXt": s.d(lambda t: t.X @ t.X.T, fl) - comm(s.Phi, XX),
            "dPhi": s.d(lambda t: t.Phi, fl) - comm(XX, s.A)}


@claim("u64-lax-reciprocal", paper="LA1", kind="lax", sizes=admissible(n_max=4))
def lax_reciprocal(s):
    """(LA1) in the reciprocal parameter μ = 1/λ, polynomial form: for L̂(μ) = μ²XXᵀ + μΦ − A,
    μ dL̂/dt = [μΦ − A, L̂] along the Dirac flow of H_{neum,κ} (generic κ)."""
    fl = s.dirac_flow(H_kappa)
    Lh = L_hat(s)
    return {"lax": s.lam * s.d(L_hat, fl) - comm(s.lam * s.Phi - s.A, Lh)}


@claim("u64-normal-energy-any-kappa", paper="LA1/perelomov", kind="pb", sizes=admissible(n_max=4))
def normal_energy_conserved(s):
    """The λ²-coefficient of tr L(λ)²: ½⟨Φ,Φ⟩ + ½tr XᵀAX (= −¼tr Φ² + ½tr XᵀAX) is conserved
    along the Neumann flow for every κ (not only for κ = 0, where it is the Hamiltonian)."""
    fl = s.dirac_flow(H_kappa)
    return {"dE": s.d(lambda t: -t.tr(t.Phi @ t.Phi) / 4 + t.tr(t.X.T @ t.A @ t.X) / 2, fl)}


@claim("u64-trL3-conserved", paper="perelomov", kind="pb", sizes=admissible(n_max=4))
def trL3_conserved(s):
    """tr L(λ)³ (k = 3 in (perelomov)) is a first integral of (No) for every κ and λ."""
    fl = s.dirac_flow(H_kappa)

    def trL3(t):
        L = t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
        return t.tr(L @ L @ L)
    return {"dtrL3": s.d(trL3, fl)}


@claim("u64-flows-differ", paper="No/grassmannian", kind="id", sizes=admissible(n_max=4))
def flows_differ(s):
    """The flow of H_κ minus the Euclidean one (κ = −½) is (1+2κ)(−XPᵀX, PXᵀP): it vanishes on Ψ⁻¹(0)."""
    fk, fe = s.dirac_flow(H_kappa), s.dirac_flow(H_eucl)
    c = 1 + 2 * s.kappa
    return {"X": fk["X"] - fe["X"] + c * (s.X @ s.P.T @ s.X),
            "P": fk["P"] - fe["P"] - c * (s.P @ s.X.T @ s.P)}


@claim("u64-gras-r2", paper="neum-gras", kind="id",
       sizes=admissible(n_min=2, r_min=2, r_max=2, n_max=5, condition="r = 2"))
def gras_r2(s):
    """(neum-gras) at r = 2 with e₁∧e₂ = e₁e₂ᵀ − e₂e₁ᵀ, along the Euclidean Neumann flow (NE_XP), at
    every point of T*V: d²/dt²(e₁∧e₂) = −Ae₁∧e₂ − e₁∧Ae₂ + 2ė₁∧ė₂ + tr(XᵀAX − ẊᵀẊ) e₁∧e₂."""
    fl = s.dirac_flow(H_eucl)
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)

    def w_dot(t):  # d/dt (e1∧e2) with ė = p (Euclidean flow)
        return wedge(t.P @ E1, t.X @ E2) + wedge(t.X @ E1, t.P @ E2)
    e1, e2, p1, p2 = s.X @ E1, s.X @ E2, s.P @ E1, s.P @ E2
    lam = s.tr(s.X.T @ s.A @ s.X - s.P.T @ s.P)
    rhs = -wedge(s.A @ e1, e2) - wedge(e1, s.A @ e2) + 2 * wedge(p1, p2) + lam * wedge(e1, e2)
    return {"xdot=p": fl["X"] - s.P, "neum-gras": s.d(w_dot, fl) - rhs}


@claim("u64-psi0-flows-coincide", paper="grassmannian", kind="id", sizes=admissible(n_max=4))
def psi0_flows_coincide(s):
    """At a point of Ψ⁻¹(0) (X, P₀ = P − XXᵀP, so XᵀP₀ = 0) the normal (N0_XP2) and Euclidean (NE_XP)
    Neumann vector fields coincide."""
    P0 = s.P - s.X @ s.X.T @ s.P
    h = twisted.at_point(s, s.X, P0)
    fn, fe = h.dirac_flow(H_normal), h.dirac_flow(H_eucl)
    return {"on V": s.X.T @ P0, "X": fn["X"] - fe["X"], "P": fn["P"] - fe["P"]}


@claim("u64-sphere-n3", paper="neum-gras**", kind="id",
       sizes=admissible(n_min=3, stated_n_max=3, r_min=2, r_max=2, condition="n = 3, r = 2"))
def sphere_n3(s):
    """r = n − 1 at n = 3: on Ψ⁻¹(0), e₃ = e₁ × e₂ moves by the Neumann system on S² with potential
    −½⟨Ae₃,e₃⟩: ë₃ = Ae₃ − (⟨Ae₃,e₃⟩ + |ė₃|²)e₃ (Euclidean flow at (X, P − XXᵀP))."""
    P0 = s.P - s.X @ s.X.T @ s.P
    h = twisted.at_point(s, s.X, P0)
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)

    def e3dot(t):
        return cross_col(t, t.P @ E1, t.X @ E2) + cross_col(t, t.X @ E1, t.P @ E2)
    e3 = cross_col(s, s.X @ E1, s.X @ E2)
    v3 = e3dot(h)
    acc = h.d(e3dot, h.dirac_flow(H_eucl))
    rhs = s.A @ e3 - ((e3.T @ s.A @ e3)[0, 0] + (v3.T @ v3)[0, 0]) * e3
    return {"sphere": acc - rhs}


@claim("u64-mag-normal-lax", paper="mag-nor/LA1", kind="lax",
       sizes=admissible(n_min=2, r_min=2, r_max=2, n_max=5, condition="r = 2"))
def mag_normal_lax(s):
    """Appendix 1: along the magnetic normal flow (H of the normal metric, form ω_ε), (LA1) holds with
    Φ_ε = Φ + ε e₁∧e₂ in place of Φ: dL_ε/dt = [Φ_ε − λA, L_ε], L_ε = λΦ_ε + XXᵀ − λ²A."""
    fl = twisted.flow(s, H_normal)
    L, Pe = L_eps(s)
    return {"lax": s.d(lambda t: L_eps(t)[0], fl) - comm(Pe - s.lam * s.A, L)}


@claim("u64-mag-psi12", paper="mag-euk/mag-nor", kind="pb",
       sizes=admissible(n_min=2, r_min=2, r_max=2, n_max=5, condition="r = 2"))
def mag_psi12(s):
    """Ψ₁₂ = (e₁,p₂) − (e₂,p₁) is conserved by both magnetic flows (mag-euk), (mag-nor)."""
    psi = lambda t: (t.X.T @ t.P - t.P.T @ t.X)[0, 1]
    return {"euk": s.d(psi, twisted.flow(s, H_eucl)), "nor": s.d(psi, twisted.flow(s, H_normal))}


@claim("u64-double-gl-momentum", paper="D-eq/dual-D", kind="pb", sizes=admissible(n_max=4))
def double_gl_momentum(s):
    """Double Neumann system (D-eq): the whole r×r matrix XᵀẎ is conserved (the paper's
    XᵀẎ − YᵀẊ is its symmetric part times 1, since YᵀẊ = −ẎᵀX on (D0))."""
    z = systems.double_point(s)
    tan = double_tangent(s, z)
    return {"XtYdot": systems.derivative(s, lambda t, w: w["X"].T @ w["Ydot"], z, tan),
            "paper": systems.derivative(s, lambda t, w: w["X"].T @ w["Ydot"] - w["Y"].T @ w["Xdot"], z, tan)}


@claim("u64-coupled-diag-momentum", paper="C-eq", kind="pb", sizes=admissible(n_max=4))
def coupled_diag_momentum(s):
    """Coupled Neumann system (C-neumann), any κ: the diagonal right SO(r) momentum
    XᵀP − PᵀX + YᵀQ − QᵀY is conserved by the Hamiltonian flow on T*V × T*V."""
    z = systems.coupled_point(s)
    fl = systems.stiefel_pairs_flow(s, coupled_H(lambda t: t.kappa), z, [("X", "P"), ("Y", "Q")])
    mom = lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"] + w["Y"].T @ w["Q"] - w["Q"].T @ w["Y"]
    return {"dmom": systems.derivative(s, mom, z, fl)}
