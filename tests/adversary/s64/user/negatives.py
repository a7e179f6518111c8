# ruff: noqa
"""False twins of claims.py (s64): each must be refuted (kind="not", expect="nonzero")."""
from stiefelsym import admissible, claim, comm, twisted, systems
from _common import (H_kappa, H_normal, H_eucl, no_flow, wedge, L_hat, L_eps, cross_col,
                     coupled_H, double_tangent)

NOT = dict(kind="not", expect="nonzero")


@claim("n64-prep-kappa", paper="prep", sizes=admissible(n_min=2, n_max=4, where=lambda n, r: r < n,
       condition="r < n (XXᵀ = I at r = n)"), **NOT)
def prep_wrong_order(s):
    """Twin of u64-prep-kappa: d(XXᵀ)/dt = [XXᵀ, Φ] (commutator reversed)."""
    fl = no_flow(s)
    return {"dXXt": s.d(lambda t: t.X @ t.X.T, fl) - comm(s.X @ s.X.T, s.Phi)}


@claim("n64-lax-reciprocal", paper="LA1", sizes=admissible(n_max=4, where=lambda n, r: r < n,
       n_min=2, condition="r < n"), **NOT)
def lax_reciprocal_transposed(s):
    """Twin: μ dL̂/dt = [L̂, μΦ − A] (the two factors swapped)."""
    fl = s.dirac_flow(H_kappa)
    return {"lax": s.lam * s.d(L_hat, fl) - comm(L_hat(s), s.lam * s.Phi - s.A)}


@claim("n64-normal-energy-any-kappa", paper="LA1/perelomov",
       sizes=admissible(n_min=2, n_max=4, where=lambda n, r: r < n, condition="r < n"), **NOT)
def energy_wrong_sign(s):
    """Twin: ½⟨Φ,Φ⟩ − ½tr XᵀAX conserved (sign of the potential)."""
    fl = s.dirac_flow(H_kappa)
    return {"dE": s.d(lambda t: -t.tr(t.Phi @ t.Phi) / 4 - t.tr(t.X.T @ t.A @ t.X) / 2, fl)}


@claim("n64-trL3-conserved", paper="perelomov",
       sizes=admissible(n_min=2, n_max=4, where=lambda n, r: r < n, condition="r < n"), **NOT)
def trL3_wrong(s):
    """Twin: tr (λΦ + XXᵀ + λ²A)³ conserved (sign of λ²A)."""
    fl = s.dirac_flow(H_kappa)

    def trL3(t):
        L = t.lam * t.Phi + t.X @ t.X.T + t.lam * t.lam * t.A
        return t.tr(L @ L @ L)
    return {"dtrL3": s.d(trL3, fl)}


@claim("n64-flows-differ", paper="No/grassmannian",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2 (XᵀP = 0 at r = 1)"), **NOT)
def flows_differ_factor2(s):
    """Twin: the difference is (2+2κ)(−XPᵀX, PXᵀP) (a factor)."""
    fk, fe = s.dirac_flow(H_kappa), s.dirac_flow(H_eucl)
    c = 2 + 2 * s.kappa
    return {"X": fk["X"] - fe["X"] + c * (s.X @ s.P.T @ s.X)}


@claim("n64-gras-r2", paper="neum-gras",
       sizes=admissible(n_min=2, r_min=2, r_max=2, n_max=5, condition="r = 2"), **NOT)
def gras_r2_factor(s):
    """Twin: (neum-gras) with ė₁∧ė₂ in place of 2ė₁∧ė₂ (factor 2)."""
    fl = s.dirac_flow(H_eucl)
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)

    def w_dot(t):
        return wedge(t.P @ E1, t.X @ E2) + wedge(t.X @ E1, t.P @ E2)
    e1, e2, p1, p2 = s.X @ E1, s.X @ E2, s.P @ E1, s.P @ E2
    lam = s.tr(s.X.T @ s.A @ s.X - s.P.T @ s.P)
    rhs = -wedge(s.A @ e1, e2) - wedge(e1, s.A @ e2) + wedge(p1, p2) + lam * wedge(e1, e2)
    return {"neum-gras": s.d(w_dot, fl) - rhs}


@claim("n64-psi0-flows-coincide", paper="grassmannian",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"), **NOT)
def flows_coincide_everywhere(s):
    """Twin: the normal and Euclidean Neumann fields coincide at every point (not only on Ψ⁻¹(0))."""
    fn, fe = s.dirac_flow(H_normal), s.dirac_flow(H_eucl)
    return {"X": fn["X"] - fe["X"], "P": fn["P"] - fe["P"]}


@claim("n64-sphere-n3", paper="neum-gras**",
       sizes=admissible(n_min=3, stated_n_max=3, r_min=2, r_max=2, condition="n = 3, r = 2"), **NOT)
def sphere_wrong_sign(s):
    """Twin: ë₃ = −Ae₃ + (⟨Ae₃,e₃⟩ − |ė₃|²)e₃ (the potential +½⟨Ae₃,e₃⟩)."""
    P0 = s.P - s.X @ s.X.T @ s.P
    h = twisted.at_point(s, s.X, P0)
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)

    def e3dot(t):
        return cross_col(t, t.P @ E1, t.X @ E2) + cross_col(t, t.X @ E1, t.P @ E2)
    e3 = cross_col(s, s.X @ E1, s.X @ E2)
    v3 = e3dot(h)
    acc = h.d(e3dot, h.dirac_flow(H_eucl))
    rhs = -(s.A @ e3) + ((e3.T @ s.A @ e3)[0, 0] - (v3.T @ v3)[0, 0]) * e3
    return {"sphere": acc - rhs}


@claim("n64-mag-normal-lax", paper="mag-nor/LA1",
       sizes=admissible(n_min=3, r_min=2, r_max=2, n_max=5, condition="r = 2, n >= 3"), **NOT)
def mag_lax_minus_eps(s):
    """Twin: the magnetic Lax pair with Φ_ε = Φ − ε e₁∧e₂ (sign of the magnetic term)."""
    fl = twisted.flow(s, H_normal)
    L, Pe = L_eps(s, -1)
    return {"lax": s.d(lambda t: L_eps(t, -1)[0], fl) - comm(Pe - s.lam * s.A, L)}


@claim("n64-mag-psi12", paper="mag-euk/mag-nor",
       sizes=admissible(n_min=2, r_min=2, r_max=2, n_max=5, condition="r = 2"), **NOT)
def mag_psi12_A(s):
    """Twin: (e₁,Ap₂) − (e₂,Ap₁) conserved by the magnetic Euclidean flow (A inserted)."""
    psi = lambda t: (t.X.T @ t.A @ t.P - t.P.T @ t.A @ t.X)[0, 1]
    return {"euk": s.d(psi, twisted.flow(s, H_eucl))}


@claim("n64-double-gl-momentum", paper="D-eq/dual-D", sizes=admissible(n_max=4), **NOT)
def double_wrong(s):
    """Twin: XᵀẊ conserved along (D-eq) (Y replaced by X)."""
    z = systems.double_point(s)
    tan = double_tangent(s, z)
    return {"XtXdot": systems.derivative(s, lambda t, w: w["X"].T @ w["Xdot"], z, tan)}


@claim("n64-coupled-diag-momentum", paper="C-eq",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2 (XᵀP = 0 at r = 1)"), **NOT)
def coupled_single(s):
    """Twin: XᵀP − PᵀX alone (one point's right momentum) is conserved by the coupled flow."""
    z = systems.coupled_point(s)
    fl = systems.stiefel_pairs_flow(s, coupled_H(lambda t: t.kappa), z, [("X", "P"), ("Y", "Q")])
    mom = lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"]
    return {"dmom": systems.derivative(s, mom, z, fl)}
