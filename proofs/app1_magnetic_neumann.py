"""Appendix 1. Magnetic Neumann systems: the twisted symplectic form, the momentum map Φ_ε, the magnetic flows and their Lax pairs, Proposition YM.

Flows are derived, never typed in: the magnetic flows are the Hamiltonian vector fields of the printed
Hamiltonians for ω_ε = ω + ε π*ω_mag (stiefelsym.twisted: the Dirac construction with the twisted
ambient bracket), the rigid-body flows those of H_CP, H_CPB on T*V(n, n) = T*O(n) (T*SO(n) is its component det X = 1)
for the canonical form.
Two printed statements fail and are registered as errata with a correction: the sign of the Lorentz force
in the n = 3 monopole remark (ym-monopole), and the condition η_so(r) = 0 (for η_so(n−r) = 0) in the
reduction of the symmetric CPB body to V(n, r) (cpb-reduction-stiefel)."""
from __future__ import annotations

from stiefelsym import Inverse, admissible, claim, comm
from stiefelsym import twisted

from .sec5_neumann import H_neumann_euclidean, H_neumann_normal, cond_XP

SECTION = "A1"

#: V(n, 2): the magnetic form de_1 ∧ de_2 needs two columns
ON_V_N2 = admissible(n_max=5, n_min=2, r_min=2, r_max=2, condition="r = 2")
#: T*SO(n) realized as T*V(n, n) (both components of O(n) are sampled; the formulas hold on both)
ON_SO_N = admissible(n_max=5, n_min=2, r_is_n=True, condition="r = n: T*V(n, n) = T*O(n), whose component det X = 1 is T*SO(n)")
#: T*V(n, n − 1), identified with T*SO(n) by (iden1)
ON_V_NN1 = admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1")


# -- vectors, wedges and columns -----------------------------------------------------------

def unit(s, i):
    """The i-th standard basis vector of ℝʳ (a column, i from 0)."""
    return twisted.basis_vector(s, i)


def col(s, i):
    """e_{i+1} = X E_{i+1}."""
    return s.X @ unit(s, i)


def pcol(s, i):
    """p_{i+1} = P E_{i+1}."""
    return s.P @ unit(s, i)


def dot(s, x, y):
    """(x, y) = xᵀy for columns x, y."""
    return s.tr(x.T @ y)


def wedge(x, y):
    """x ∧ y = x ⊗ y − y ⊗ x = xyᵀ − yxᵀ."""
    return x @ y.T - y @ x.T


def columns_to_matrix(s, vectors):
    """The n × r matrix with the given columns."""
    out = vectors[0] @ unit(s, 0).T
    for i, v in enumerate(vectors[1:], start=1):
        out = out + v @ unit(s, i).T
    return out


def projector(s, k):
    """D_k = diag(1, ..., 1, 0, ..., 0) (k ones) on ℝʳ."""
    return twisted.coordinate_projector(s, k)


# -- the twisted form on T*V(n, 2) -------------------------------------------------------------

def e1e2(s):
    """e₁ ∧ e₂ = XJXᵀ, J = E₁∧E₂ ∈ so(2)."""
    return wedge(col(s, 0), col(s, 1))


def Phi_eps(s):
    """(mag-mom-stief): Φ_ε = Φ + ε e₁∧e₂."""
    return s.Phi + s.eps * e1e2(s)


def Phi_eps_xi(s):
    """⟨Φ_ε, ξ⟩."""
    return s.killing(Phi_eps(s), s.xi)


def Phi_eps_zeta(s):
    """⟨Φ_ε, ζ⟩."""
    return s.killing(Phi_eps(s), s.zeta)


def H_linear(s):
    """H = tr(UᵀX) + tr(VᵀP) with generic U, V: its differential is a generic covector."""
    return s.tr(s.generic("U", "n", "r").T @ s.X) + s.tr(s.generic("V", "n", "r").T @ s.P)


def tangent_vector(s):
    """A generic tangent vector of T*V at (X, P): (ξX, ξP + Xη + (I − XXᵀ)Z) with ξ ∈ so(n), η ∈ so(r)
    (for r < n the vectors ξX span T_XV, and Xη + (I − XXᵀ)Z spans the fibre directions)."""
    Z = s.generic("Z", "n", "r")
    return {"X": s.xi @ s.X, "P": s.xi @ s.P + s.X @ s.eta + (s.In - s.X @ s.X.T) @ Z}


def twisted_constraint_brackets(s, S, T):
    """{F_i, F_j}_ε as an operator on Sym(r) × Sym(r): (S, T) ↦ dF(X^ε_h) for h = tr(S F_1) + tr(T F_2) and
    X^ε_h its Hamiltonian vector field for ω₀ + ε de₁∧de₂ on ℝ^{4n}, Ẋ = h_P, Ṗ = −h_X − ε h_P F (as
    twisted.ambient_flow): the matrix {F_i, F_j}_ε applied to the coefficients of h."""
    def h(t):
        F1, F2 = cond_XP(t)
        return t.tr(S @ F1) + t.tr(T @ F2)
    canonical = s.canonical_flow(h)    # (h_P, −h_X)
    F = twisted.magnetic_matrix(s)
    return tuple(s.d(cond_XP, {"X": canonical.Xdot, "P": canonical.Pdot - s.eps * (canonical.Xdot @ F)}))


def twisted_constraint_brackets_inverse(s, a, b):
    """Its inverse on T*V_{n,2}: T = a/4, S = (aK − Ka − b)/4 − ε(aF − Fa)/8 with K = XᵀP, F = E₁∧E₂ (the
    operator is (4T, 4(TK − KT) − 4S − 2ε(TF − FT)) there)."""
    K = s.X.T @ s.P
    F = twisted.magnetic_matrix(s)
    return (a @ K - K @ a - b) / 4 - s.eps * (a @ F - F @ a) / 8, a / 4


@claim("twisted-form", paper=("twisted",), kind="pb", sizes=ON_V_N2,
       equivariance="the operator {F_i, F_j}_eps on Sym(r) x Sym(r) of the O(n)-invariant constraints for the O(n)-invariant form, and its inverse, are matrix expressions in X, P; no coordinate of R^n is read",
       statement=r"\omega_\epsilon=\omega+\epsilon\,\pi^*\omega_{mag},\ \omega_{mag}=de_1\wedge de_2:\quad "
                 r"\det\big(\{F_i,F_j\}_\epsilon\big)\ne0,\quad X_H\in T(T^*V_{n,2}),\quad "
                 r"\omega_\epsilon(X_H,v)=-dH(v)\ \ \forall v\in T(T^*V_{n,2})")
def twisted_form_is_symplectic(s):
    """The twisted form ω_ε = ω + ε π*ω_mag is symplectic on T*V_{n,2}: ω₀ + ε de₁∧de₂ is a constant (closed, nondegenerate) form on ℝ^{4n}, the constraints (cond_XP) stay second class for its bracket, and the Dirac flow of every H (a linear H with generic differential suffices) is tangent to T*V and satisfies ω_ε(X_H, v) = −dH(v) for every v tangent to T*V, so the twisted Dirac bracket is the Poisson bracket of ω_ε."""
    XH = twisted.flow(s, H_linear)
    v = tangent_vector(s)
    return {
        "{F_i, F_j}_eps invertible": Inverse(twisted_constraint_brackets, twisted_constraint_brackets_inverse,
                                             on=("Sym(r)", "Sym(r)"),
                                             meaning="T*V is a symplectic submanifold for the twisted ambient form"),
        "X_H tangent to T*V": s.d(cond_XP, XH),
        "v tangent to T*V": s.d(cond_XP, v),
        "omega_eps(X_H, v) + dH(v)": twisted.form(s, XH.tangent(), v) + s.d(H_linear, v),
    }


def jacobi_test_functions(s):
    """Three functions with generic differentials and Hessians: ⟨Φ, ξ⟩, tr(GPᵀP), ½tr(XᵀAX) + tr(UᵀP)."""
    return (lambda t: t.killing(t.Phi, t.xi),
            lambda t: t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P),
            lambda t: t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.generic("U", "n", "r").T @ t.P))


@claim("twisted-form-closed", paper=("twisted",), kind="pb",
       sizes=admissible(n_max=3, n_min=2, r_min=2, r_max=2, condition="r = 2"),
       statement=r"d\omega_\epsilon=0:\quad \{f,\{g,h\}_\epsilon\}_\epsilon+\{g,\{h,f\}_\epsilon\}_\epsilon+\{h,\{f,g\}_\epsilon\}_\epsilon=0")
def twisted_form_is_closed(s):
    """The Dirac bracket of the twisted form satisfies the Jacobi identity (ω_ε = ω + ε π*ω_mag is closed; checked on three functions with generic second derivatives, a few seconds per size, so by default at n ≤ 3)."""
    f, g, h = jacobi_test_functions(s)
    b = lambda F, G: (lambda t: twisted.bracket(t, F, G))
    return {"Jacobi": twisted.bracket(s, f, b(g, h)) + twisted.bracket(s, g, b(h, f)) + twisted.bracket(s, h, b(f, g))}


@claim("magnetic-form-kirillov-kostant", paper=("twisted", "mag-mom-grass"), kind="pb", sizes=ON_V_N2,
       statement=r"\omega_{mag}(X\eta,v)=0\ (v\in T_XV_{n,2}),\quad "
                 r"\omega_{mag}(\xi X,\zeta X)=-\langle e_1\wedge e_2,[\xi,\zeta]\rangle=\omega^-_{KK}([\xi,G],[\zeta,G]),\ G=e_1\wedge e_2")
def magnetic_form_is_kirillov_kostant(s):
    """The magnetic form ω_mag = de₁∧de₂ is basic for V_{n,2} → G_{n,2} (it vanishes on the right SO(2) directions Xη) and on G_{n,2} ≅ the adjoint orbit of E₁∧E₂ it is the Kirillov–Kostant form, ω_mag(ξX, ζX) = −⟨e₁∧e₂, [ξ, ζ]⟩ for the tangent vectors [ξ, G], [ζ, G] of the orbit (the ω⁻ convention), so επ*ω_mag is ε times the Kirillov–Kostant form, as the paper says."""
    zero = s.zeros(s.n, s.r, ("n", "r"))
    G = e1e2(s)
    along = lambda a: {"X": a, "P": zero}
    return {
        "omega_mag(X eta, xi X)": twisted.form(s, along(s.X @ s.eta), along(s.xi @ s.X)),
        "omega_mag(xi X, zeta X) + <G, [xi, zeta]>": twisted.form(s, along(s.xi @ s.X), along(s.zeta @ s.X))
        + s.eps * s.killing(G, comm(s.xi, s.zeta)),
        "d/ds G(e^{s xi} X) = [xi, G]": s.d(e1e2, along(s.xi @ s.X)) - comm(s.xi, G),
    }


@claim("magnetic-momentum-map", paper=("mag-mom-stief", "twisted"), kind="pb", sizes=ON_V_N2,
       statement=r"\Phi_\epsilon=\Phi+\epsilon\,e_1\wedge e_2=p_1\wedge e_1+p_2\wedge e_2+\epsilon\,e_1\wedge e_2:\quad "
                 r"X^{\epsilon}_{\langle\Phi_\epsilon,\xi\rangle}=(\xi X,\xi P),\quad "
                 r"\tfrac{d}{ds}\Phi_\epsilon(e^{s\xi}X,e^{s\xi}P)\big|_{s=0}=[\xi,\Phi_\epsilon],\quad "
                 r"\{\langle\Phi_\epsilon,\xi\rangle,\langle\Phi_\epsilon,\zeta\rangle\}_\epsilon=\langle\Phi_\epsilon,[\xi,\zeta]\rangle")
def phi_eps_is_the_twisted_momentum_map(s):
    """The left SO(n) action on (T*V_{n,2}, ω_ε) is Hamiltonian with momentum map Φ_ε = p₁∧e₁ + p₂∧e₂ + εe₁∧e₂: the Hamiltonian vector field of ⟨Φ_ε, ξ⟩ for the twisted form is the infinitesimal action (ξX, ξP), Φ_ε is equivariant, and it is a Poisson map to so(n) with the (+) Lie–Poisson bracket."""
    e1, e2, p1, p2 = col(s, 0), col(s, 1), pcol(s, 0), pcol(s, 1)
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    flow = twisted.flow(s, Phi_eps_xi)
    return {
        "Phi + eps e1^e2 = p1^e1 + p2^e2 + eps e1^e2": Phi_eps(s) - (wedge(p1, e1) + wedge(p2, e2) + s.eps * wedge(e1, e2)),
        "dX/dt = xi X": flow.Xdot - left["X"],
        "dP/dt = xi P": flow.Pdot - left["P"],
        "equivariance": s.d(Phi_eps, left) - comm(s.xi, Phi_eps(s)),
        "{Phi_eps_xi, Phi_eps_zeta}_eps (+)": twisted.bracket(s, Phi_eps_xi, Phi_eps_zeta)
        - s.killing(Phi_eps(s), comm(s.xi, s.zeta)),
    }


# -- the magnetic Neumann flows (mag-euk), (mag-nor) ------------------------------------------------

def twisted_flow_checks(s, H, printed):
    """The twisted Dirac flow of H equals the printed flow, and the printed flow keeps T*V."""
    flow = twisted.flow(s, H)
    kept = s.d(cond_XP, printed)
    return {
        "dX/dt": flow.Xdot - printed["X"],
        "dP/dt": flow.Pdot - printed["P"],
        "d(X^T X)/dt along the printed flow": kept[0],
        "d(X^T P + P^T X)/dt along the printed flow": kept[1],
    }


@claim("magnetic-euclidean-flow", paper=("mag-euk", "twisted", "neumann"), kind="id", sizes=ON_V_N2,
       statement=r"\dot e_i=p_i,\ \dot p_1=-Ae_1+\big((e_1,Ae_1)-(p_1,p_1)-\epsilon(e_1,p_2)\big)e_1+\big((e_1,Ae_2)-(p_1,p_2)\big)e_2+\epsilon p_2,"
                 r"\ \dot p_2=-Ae_2+\big((e_1,Ae_2)-(p_1,p_2)\big)e_1+\big((e_2,Ae_2)-(p_2,p_2)+\epsilon(e_2,p_1)\big)e_2-\epsilon p_1")
def magnetic_neumann_euclidean_flow(s):
    """The Hamiltonian flow of the Euclidean Neumann Hamiltonian H_neum,−½ for the twisted form ω + ε π*ω_mag on T*V_{n,2} is the printed (mag-euk), which is tangent to T*V."""
    A, eps = s.A, s.eps
    e1, e2, p1, p2 = col(s, 0), col(s, 1), pcol(s, 0), pcol(s, 1)
    d = lambda x, y: dot(s, x, y)
    p1dot = (-(A @ e1) + (d(e1, A @ e1) - d(p1, p1) - eps * d(e1, p2)) * e1
             + (d(e1, A @ e2) - d(p1, p2)) * e2 + eps * p2)
    p2dot = (-(A @ e2) + (d(e1, A @ e2) - d(p1, p2)) * e1
             + (d(e2, A @ e2) - d(p2, p2) + eps * d(e2, p1)) * e2 - eps * p1)
    printed = {"X": columns_to_matrix(s, [p1, p2]), "P": columns_to_matrix(s, [p1dot, p2dot])}
    return twisted_flow_checks(s, H_neumann_euclidean, printed)


@claim("magnetic-normal-flow", paper=("mag-nor", "twisted", "neumann"), kind="id", sizes=ON_V_N2,
       statement=r"\dot e_1=\Phi_0e_1=p_1-(e_1,p_2)e_2,\ \dot e_2=\Phi_0e_2=p_2-(e_2,p_1)e_1,\ "
                 r"\dot p_1=\Phi_0p_1-Ae_1+\big((e_1,Ae_1)-\epsilon(e_1,\Phi_0e_2)\big)e_1+(e_1,Ae_2)e_2+\epsilon\Phi_0e_2,\ "
                 r"\dot p_2=\Phi_0p_2-Ae_2+(e_2,Ae_1)e_1+\big((e_2,Ae_2)+\epsilon(e_2,\Phi_0e_1)\big)e_2-\epsilon\Phi_0e_1")
def magnetic_neumann_normal_flow(s):
    """The Hamiltonian flow of the normal-metric Neumann Hamiltonian H_neum,0 for the twisted form on T*V_{n,2} is the printed (mag-nor) with Φ₀ = Φ, which is tangent to T*V, and Φ₀e₁ = p₁ − (e₁, p₂)e₂, Φ₀e₂ = p₂ − (e₂, p₁)e₁ on T*V."""
    A, eps, Phi0 = s.A, s.eps, s.Phi
    e1, e2, p1, p2 = col(s, 0), col(s, 1), pcol(s, 0), pcol(s, 1)
    d = lambda x, y: dot(s, x, y)
    p1dot = (Phi0 @ p1 - A @ e1 + (d(e1, A @ e1) - eps * d(e1, Phi0 @ e2)) * e1 + d(e1, A @ e2) * e2
             + eps * (Phi0 @ e2))
    p2dot = (Phi0 @ p2 - A @ e2 + d(e2, A @ e1) * e1 + (d(e2, A @ e2) + eps * d(e2, Phi0 @ e1)) * e2
             - eps * (Phi0 @ e1))
    printed = {"X": columns_to_matrix(s, [Phi0 @ e1, Phi0 @ e2]), "P": columns_to_matrix(s, [p1dot, p2dot])}
    checks = twisted_flow_checks(s, H_neumann_normal, printed)
    checks["Phi_0 e1 = p1 - (e1, p2) e2"] = Phi0 @ e1 - (p1 - d(e1, p2) * e2)
    checks["Phi_0 e2 = p2 - (e2, p1) e1"] = Phi0 @ e2 - (p2 - d(e2, p1) * e1)
    return checks


def psi12(s):
    """Ψ₁₂ = (e₁, p₂) − (e₂, p₁)."""
    return dot(s, col(s, 0), pcol(s, 1)) - dot(s, col(s, 1), pcol(s, 0))


@claim("magnetic-psi12-conserved", paper=("mag-euk", "mag-nor"), kind="pb", sizes=ON_V_N2,
       statement=r"\Psi_{12}=(e_1,p_2)-(e_2,p_1):\quad \tfrac{d}{dt}\Psi_{12}=\{\Psi_{12},H\}_\epsilon=0\ "
                 r"\text{along (mag-euk), (mag-nor)};\quad H(Xe^{s\eta},Pe^{s\eta})=H")
def psi12_is_an_integral_of_the_magnetic_flows(s):
    """The magnetic Neumann flows (mag-euk) and (mag-nor) are right SO(2)-invariant (so are their Hamiltonians and ω_ε) and have the integral Ψ₁₂ = (e₁, p₂) − (e₂, p₁): it is still the momentum map of the right SO(2) action for ω_ε (its twisted Hamiltonian vector field is (XJ, PJ), J = E₁∧E₂), and its twisted bracket with either Hamiltonian vanishes."""
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    checks = {}
    for name, H in (("mag-euk", H_neumann_euclidean), ("mag-nor", H_neumann_normal)):
        checks[f"dPsi12/dt along ({name})"] = s.d(psi12, twisted.flow(s, H))
        checks[f"{{Psi12, H}}_eps ({name})"] = twisted.bracket(s, psi12, H)
        checks[f"H right SO(2)-invariant ({name})"] = s.d(H, right)
    u = {"X": s.generic("U1", "n", "r"), "P": s.generic("U2", "n", "r")}
    v = {"X": s.generic("V1", "n", "r"), "P": s.generic("V2", "n", "r")}
    moved = lambda w: {"X": w["X"] @ s.eta, "P": w["P"] @ s.eta}
    checks["omega_eps right SO(2)-invariant"] = twisted.form(s, moved(u), v) + twisted.form(s, u, moved(v))
    J = twisted.magnetic_matrix(s)
    generated = twisted.flow(s, psi12)
    checks["Psi12 generates the right SO(2) action for omega_eps (X)"] = generated.Xdot - s.X @ J
    checks["Psi12 generates the right SO(2) action for omega_eps (P)"] = generated.Pdot - s.P @ J
    return checks


# -- (prep) and the Lax pair with Φ_ε -------------------------------------------------------------

MAGNETIC_HAMILTONIANS = (("mag-euk", H_neumann_euclidean), ("mag-nor", H_neumann_normal))


@claim("magnetic-prep", paper=("prep", "mag-euk", "mag-nor", "mag-mom-stief"), kind="id", sizes=ON_V_N2,
       statement=r"\tfrac{d}{dt}\Phi_\epsilon=[e_1\otimes e_1+e_2\otimes e_2,A],\quad "
                 r"\tfrac{d}{dt}(e_1\otimes e_1+e_2\otimes e_2)=[\Phi_\epsilon,e_1\otimes e_1+e_2\otimes e_2]\ "
                 r"\text{along (mag-euk), (mag-nor)}")
def magnetic_prep(s):
    """Along both magnetic Neumann flows (mag-euk) and (mag-nor), derived from the twisted form, (prep) holds with Φ_ε in place of Φ: dΦ_ε/dt = [XXᵀ, A] and d(XXᵀ)/dt = [Φ_ε, XXᵀ], XXᵀ = e₁⊗e₁ + e₂⊗e₂."""
    XX = s.X @ s.X.T
    checks = {}
    for name, H in MAGNETIC_HAMILTONIANS:
        flow = twisted.flow(s, H)
        checks[f"dPhi_eps/dt ({name})"] = s.d(Phi_eps, flow) - comm(XX, s.A)
        checks[f"d(XX^T)/dt ({name})"] = s.d(lambda t: t.X @ t.X.T, flow) - comm(Phi_eps(s), XX)
    return checks


def L_mag(s):
    """(LA2) with Φ_ε: 𝓛(λ) = λΦ_ε + XXᵀ − λ²A."""
    return s.lam * Phi_eps(s) + s.X @ s.X.T - s.lam * s.lam * s.A


def A_mag(s):
    """(LA2) with Φ_ε: 𝓐(λ) = Φ_ε − λA."""
    return Phi_eps(s) - s.lam * s.A


@claim("magnetic-lax", paper=("LA1", "LA2", "mag-euk", "mag-nor", "mag-mom-stief"), kind="lax", sizes=ON_V_N2,
       statement=r"\tfrac{d}{dt}\mathcal L(\lambda)=[\mathcal A(\lambda),\mathcal L(\lambda)],\quad "
                 r"\mathcal L=\lambda\Phi_\epsilon+XX^T-\lambda^2A,\ \mathcal A=\Phi_\epsilon-\lambda A\ "
                 r"\text{along (mag-euk), (mag-nor)}")
def magnetic_lax_pair(s):
    """Both magnetic Neumann flows (mag-euk) and (mag-nor), derived from the twisted form, imply the Lax representation (LA1), (LA2) with the momentum map Φ_ε of (mag-mom-stief) in place of Φ."""
    checks = {}
    for name, H in MAGNETIC_HAMILTONIANS:
        checks[f"LA1 ({name})"] = s.d(L_mag, twisted.flow(s, H)) - comm(A_mag(s), L_mag(s))
    return checks


# -- every rank: a magnetic term ε Σ F_jk de_j∧de_k with a generic F ∈ so(r) --------------------------

def Phi_F(s):
    """Φ_F = Φ + εXFXᵀ for the generic F = η ∈ so(r) (r = 2: F = η₁₂E₁∧E₂, XFXᵀ = η₁₂ e₁∧e₂)."""
    return s.Phi + s.eps * (s.X @ s.eta @ s.X.T)


def H_neumann_kappa(s):
    """(neumann) with a free κ."""
    XtP = s.X.T @ s.P
    return (s.tr(s.P.T @ s.P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(XtP @ XtP)
            + s.tr(s.X.T @ s.A @ s.X) / 2)


@claim("magnetic-momentum-map-any-rank", paper=("mag-mom-stief", "twisted"), kind="pb",
       statement=r"\omega_F=\omega+\epsilon\,\pi^*\textstyle\sum_{j<k}F_{jk}de_j\wedge de_k,\ F\in so(r):\quad "
                 r"\Phi_F=\Phi+\epsilon XFX^T,\ X^{F}_{\langle\Phi_F,\xi\rangle}=(\xi X,\xi P),\ "
                 r"\{\langle\Phi_F,\xi\rangle,\langle\Phi_F,\zeta\rangle\}_F=\langle\Phi_F,[\xi,\zeta]\rangle")
def twisted_momentum_map_every_rank(s):
    """(mag-mom-stief) for every n, r: with the magnetic term ε Σ F_jk de_j∧de_k of a generic constant F ∈ so(r) (for r = 2, F = fE₁∧E₂ and Φ_F is Φ_ε with ε replaced by εf), Φ_F = Φ + εXFXᵀ is the equivariant momentum map of the left SO(n) action and a Poisson map."""
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    flow = twisted.flow(s, lambda t: t.killing(Phi_F(t), t.xi), F=s.eta)
    return {
        "dX/dt = xi X": flow.Xdot - left["X"],
        "dP/dt = xi P": flow.Pdot - left["P"],
        "equivariance": s.d(Phi_F, left) - comm(s.xi, Phi_F(s)),
        "{Phi_F_xi, Phi_F_zeta}_F (+)": twisted.bracket(s, lambda t: t.killing(Phi_F(t), t.xi),
                                                        lambda t: t.killing(Phi_F(t), t.zeta), F=s.eta)
        - s.killing(Phi_F(s), comm(s.xi, s.zeta)),
    }


@claim("magnetic-lax-any-rank", paper=("prep", "LA1", "LA2", "mag-euk", "mag-nor", "twisted"), kind="lax",
       statement=r"\tfrac{d}{dt}\Phi_F=[XX^T,A],\ \tfrac{d}{dt}XX^T=[\Phi_F,XX^T],\ "
                 r"\tfrac{d}{dt}\mathcal L=[\mathcal A,\mathcal L],\ \mathcal L=\lambda\Phi_F+XX^T-\lambda^2A,\ "
                 r"\mathcal A=\Phi_F-\lambda A\ \text{along the flow of } H_{neum,\kappa}\ \text{for } \omega_F")
def twisted_lax_pair_every_rank(s):
    """(prep) and the Lax pair (LA1) with the momentum map Φ_F = Φ + εXFXᵀ hold along the Hamiltonian flow of H_neum,κ for the twisted form ω_F, for every n, r, κ and generic constant F ∈ so(r) (r = 2, κ = −½, 0: (mag-euk), (mag-nor) with Φ_ε)."""
    flow = twisted.flow(s, H_neumann_kappa, F=s.eta)
    XX = s.X @ s.X.T
    L = lambda t: t.lam * Phi_F(t) + t.X @ t.X.T - t.lam * t.lam * t.A
    M = Phi_F(s) - s.lam * s.A
    return {
        "dPhi_F/dt = [XX^T, A]": s.d(Phi_F, flow) - comm(XX, s.A),
        "d(XX^T)/dt = [Phi_F, XX^T]": s.d(lambda t: t.X @ t.X.T, flow) - comm(Phi_F(s), XX),
        "LA1": s.d(L, flow) - comm(M, L(s)),
    }


# -- the magnetic Neumann system on G(n, 2) -------------------------------------------------------

def horizontal_point(s):
    """(X, P_h), P_h = (I − XXᵀ)P: a generic point of Ψ⁻¹(0) = {XᵀP = 0} (gras-velocities with ė = p)."""
    return s.X, (s.In - s.X @ s.X.T) @ s.P


def Phi_eps_grass(s, e1, e2, e1dot, e2dot):
    """(mag-mom-grass), first form: ė₁∧e₁ + ė₂∧e₂ + εe₁∧e₂."""
    return wedge(e1dot, e1) + wedge(e2dot, e2) + s.eps * wedge(e1, e2)


def Phi_eps_grass_commutator(s, e1, e2, e1dot, e2dot):
    """(mag-mom-grass), second form: [e₁∧e₂, ė₁∧e₂ + e₁∧ė₂] + εe₁∧e₂."""
    return comm(wedge(e1, e2), wedge(e1dot, e2) + wedge(e1, e2dot)) + s.eps * wedge(e1, e2)


def grass_momentum_of(t):
    """Φ_ε of (mag-mom-grass) at (X, (I − XXᵀ)P), as a function of the scene."""
    X, Ph = horizontal_point(t)
    e1, e2 = X @ unit(t, 0), X @ unit(t, 1)
    return Phi_eps_grass(t, e1, e2, Ph @ unit(t, 0), Ph @ unit(t, 1))


@claim("magnetic-grassmannian-momentum", paper=("mag-mom-grass", "gras-velocities", "mag-mom-stief"), kind="id",
       sizes=ON_V_N2,
       statement=r"(e_i,e_j)=\delta_{ij},\ (\dot e_i,e_j)=0:\quad \Phi_\epsilon=\dot e_1\wedge e_1+\dot e_2\wedge e_2+\epsilon\,e_1\wedge e_2"
                 r"=[e_1\wedge e_2,\dot e_1\wedge e_2+e_1\wedge\dot e_2]+\epsilon\,e_1\wedge e_2")
def magnetic_grassmannian_momentum(s):
    """For velocities satisfying (gras-velocities) the two forms of the magnetic momentum map (mag-mom-grass) agree, it is the Stiefel momentum map Φ_ε of (mag-mom-stief) on Ψ⁻¹(0) (where ė = p), and it is right SO(2)-invariant, so a function on the magnetic T*G_{n,2}."""
    X, Ph = horizontal_point(s)
    e1, e2 = col(s, 0), col(s, 1)
    e1dot, e2dot = Ph @ unit(s, 0), Ph @ unit(s, 1)
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    first = Phi_eps_grass(s, e1, e2, e1dot, e2dot)
    return {
        "gras-velocities (e_i, de_j/dt) = 0": X.T @ Ph,
        "two forms of (mag-mom-grass)": first - Phi_eps_grass_commutator(s, e1, e2, e1dot, e2dot),
        "= (mag-mom-stief) at (X, P_h)": first - (Ph @ X.T - X @ Ph.T + s.eps * wedge(e1, e2)),
        "right SO(2)-invariant": s.d(grass_momentum_of, right),
    }


def rhs_neum_gras_mag(s, e1, e2, e1dot, e2dot):
    """The right-hand side of (neum-gras-mag) as printed."""
    A, eps = s.A, s.eps
    d = lambda x, y: dot(s, x, y)
    lam = d(e1, A @ e1) - d(e1dot, e1dot) + d(e2, A @ e2) - d(e2dot, e2dot)
    return (-wedge(A @ e1, e2) - wedge(e1, A @ e2) + lam * wedge(e1, e2) + 2 * wedge(e1dot, e2dot)
            + eps * comm(wedge(e1, e2), wedge(e1dot, e2) + wedge(e1, e2dot)))


@claim("magnetic-grassmannian-flow", paper=("neum-gras-mag", "mag-euk", "mag-nor", "prep"), kind="id", sizes=ON_V_N2,
       statement=r"\tfrac{d^2}{dt^2}(e_1\wedge e_2)=-Ae_1\wedge e_2-e_1\wedge Ae_2+\big((e_1,Ae_1)-(\dot e_1,\dot e_1)"
                 r"+(e_2,Ae_2)-(\dot e_2,\dot e_2)\big)e_1\wedge e_2+2\dot e_1\wedge\dot e_2"
                 r"+\epsilon[e_1\wedge e_2,\dot e_1\wedge e_2+e_1\wedge\dot e_2]")
def magnetic_grassmannian_flow(s):
    """The magnetic Neumann system (neum-gras-mag) on G_{n,2} is the reduction of (mag-euk) and of (mag-nor) on Ψ⁻¹(0): at a generic point of Ψ⁻¹(0) the twisted flow keeps Ψ = 0, has ė = p, and its second derivative of e₁∧e₂ is the printed right-hand side (which keeps e₁∧e₂ a unit decomposable bivector to second order); along it (prep) holds with the Φ_ε of (mag-mom-grass)."""
    X, Ph = horizontal_point(s)
    h = twisted.at_point(s, X, Ph)
    e1, e2 = col(h, 0), col(h, 1)
    XX = X @ X.T
    checks = {"Psi at the point": h.Psi}
    for name, H in MAGNETIC_HAMILTONIANS:
        flow = twisted.flow(h, H)
        e1dot, e2dot = flow.Xdot @ unit(h, 0), flow.Xdot @ unit(h, 1)
        e1dd, e2dd = flow.Pdot @ unit(h, 0), flow.Pdot @ unit(h, 1)    # ë = d/dt p since ė = p on Ψ⁻¹(0)
        second = wedge(e1dd, e2) + 2 * wedge(e1dot, e2dot) + wedge(e1, e2dd)
        grass = Phi_eps_grass(h, e1, e2, e1dot, e2dot)
        checks[f"dPsi/dt at Psi = 0 ({name})"] = h.d(lambda t: t.Psi, flow)
        checks[f"de/dt = p on Psi = 0 ({name})"] = flow.Xdot - Ph
        checks[f"(neum-gras-mag) ({name})"] = second - rhs_neum_gras_mag(h, e1, e2, e1dot, e2dot)
        G, Gd, Gdd = wedge(e1, e2), wedge(e1dot, e2) + wedge(e1, e2dot), rhs_neum_gras_mag(h, e1, e2, e1dot, e2dot)
        checks[f"(neum-gras-mag) keeps G^3 = -G, G = e1^e2, to second order ({name})"] = (
            Gdd @ G @ G + G @ Gdd @ G + G @ G @ Gdd + 2 * (Gd @ Gd @ G + Gd @ G @ Gd + G @ Gd @ Gd) + Gdd)
        checks[f"(neum-gras-mag) keeps tr G^2 = -2 to second order ({name})"] = h.tr(Gdd @ G) + h.tr(Gd @ Gd)
        checks[f"(prep): dPhi_eps/dt = [XX^T, A] ({name})"] = (
            wedge(e1dd, e1) + wedge(e2dd, e2) + h.eps * (wedge(e1dot, e2) + wedge(e1, e2dot)) - comm(XX, h.A))
        checks[f"(prep): d(XX^T)/dt = [Phi_eps, XX^T] ({name})"] = (
            e1dot @ e1.T + e1 @ e1dot.T + e2dot @ e2.T + e2 @ e2dot.T - comm(grass, XX))
    return checks


# -- Proposition YM: the rigid body on SO(n), the component det X = 1 of V(n, n) = O(n) ------------

def last(s):
    """e_n, the last column of 𝒳 = X ∈ SO(n) (r = n)."""
    return s.X @ twisted.last_basis_vector(s)


def H_CP(s):
    """(mag*): H_CP = ½⟨M, M⟩ + ½(tr A − (e_n, Ae_n)), M = Φ = 𝒫𝒳ᵀ − 𝒳𝒫ᵀ."""
    e = last(s)
    return s.killing(s.Phi, s.Phi) / 2 + (s.tr(s.A) - dot(s, e, s.A @ e)) / 2


def stiefel_image(s):
    """(iden1) backwards: (𝒳, 𝒫) ↦ (X', P') ∈ T*V(n, n−1), X' = (e_1, ..., e_{n−1}), P' the cotangent
    lift (P' = MX' − ½X'X'ᵀMX', the unique covector with Φ(X', P') = M)."""
    Xp = s.X @ twisted.leading_basis_vectors(s)
    M = s.Phi
    return Xp, M @ Xp - Xp @ (Xp.T @ M @ Xp) / 2


def neumann_normal_at(s, X, P):
    """H_neum,0 at (X, P): ½tr(PᵀP) − ½tr((XᵀP)²) + ½tr(XᵀAX)."""
    XtP = X.T @ P
    return (s.tr(P.T @ P) - s.tr(XtP @ XtP) + s.tr(X.T @ s.A @ X)) / 2


def flow_N0_at(s, X, P):
    """(N0_XP2) at (X, P): Ẋ = P − XPᵀX, Ṗ = −AX + PXᵀP − XPᵀP + XXᵀAX."""
    A = s.A
    return {"X": P - X @ P.T @ X, "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}


def right_so_n_minus_1(s):
    """The right action of η' ∈ so(n−1) ⊂ so(n) (η' = DηD, D = diag(1, ..., 1, 0))."""
    D = s.Ir - twisted.last_basis_vector(s) @ twisted.last_basis_vector(s).T
    eta = D @ s.eta @ D
    return {"X": s.X @ eta, "P": s.P @ eta}


@claim("clebsch-perelomov-hamiltonian", paper=("mag*", "iden1", "N0_XP2"), kind="id", sizes=ON_SO_N,
       statement=r"e_n\otimes e_n=\mathbf I_n-\sum_{i=1}^{n-1}e_i\otimes e_i,\quad "
                 r"H_{neum,0}(X,P)=H_{CP}=\tfrac12\langle M,M\rangle+\tfrac12\big(\tr A-(e_n,Ae_n)\big),\quad "
                 r"M=\mathcal P\mathcal X^T-\mathcal X\mathcal P^T=\Phi(X,P)")
def clebsch_perelomov_hamiltonian(s):
    """Under (iden1), T*V_{n,n−1} ≅ T*SO(n) (the cotangent lift (𝒳, 𝒫) ↦ (X, P), X = (e₁, …, e_{n−1}), P = MX − ½XXᵀMX), the momentum maps agree, Φ(X, P) = M, the normal-metric Neumann Hamiltonian becomes the symmetric Clebsch–Perelomov Hamiltonian H_CP of (mag*), which is right SO(n−1)-invariant, and the Dirac flow of H_CP on T*SO(n) is carried to the Neumann flow (N0_XP2) on T*V_{n,n−1}."""
    e = last(s)
    E = twisted.leading_basis_vectors(s)
    Xp, Pp = stiefel_image(s)
    flow = s.dirac_flow(H_CP)
    image = flow_N0_at(s, Xp, Pp)
    return {
        "e_n (x) e_n = I - sum e_i (x) e_i": e @ e.T - (s.In - Xp @ Xp.T),
        "X'^T X' = I_{n-1}": Xp.T @ Xp - E.T @ E,
        "X'^T P' + P'^T X' = 0": Xp.T @ Pp + Pp.T @ Xp,
        "Phi(X', P') = M": Pp @ Xp.T - Xp @ Pp.T - s.Phi,
        "H_neum,0(X', P') = H_CP": neumann_normal_at(s, Xp, Pp) - H_CP(s),
        "H_CP right SO(n-1)-invariant": s.d(H_CP, right_so_n_minus_1(s)),
        "d X'/dt = (N0_XP2)": s.d(lambda t: stiefel_image(t)[0], flow) - image["X"],
        "d P'/dt = (N0_XP2)": s.d(lambda t: stiefel_image(t)[1], flow) - image["P"],
    }


@claim("rigid-body-euler-poisson", paper=("Euler*", "Poisson", "mag2", "mag*"), kind="id", sizes=ON_SO_N,
       statement=r"\Omega=\dot{\mathcal X}\mathcal X^{-1}=M,\ \omega=\mathcal X^{-1}\dot{\mathcal X}=m=\mathcal X^{-1}M\mathcal X,\quad "
                 r"\dot\Omega=[A,e_n\otimes e_n],\quad \dot e_i=\Omega e_i\ (i=1,\dots,n),\quad \dot e_n=\Omega e_n")
def rigid_body_euler_poisson(s):
    """Along the Dirac flow of H_CP on T*SO(n), the angular velocities in the space and body frames are the angular momenta, Ω = 𝒳̇𝒳⁻¹ = M and ω = 𝒳⁻¹𝒳̇ = m = 𝒳⁻¹M𝒳 (the inertia operator is the identity), and the motion obeys the Euler–Poincaré equation (Euler*) Ω̇ = [A, e_n⊗e_n] with the Poisson equations (Poisson), in particular (mag2) ė_n = Ωe_n, which keep 𝒳 orthogonal."""
    flow = s.dirac_flow(H_CP)
    e = last(s)
    Omega = flow.Xdot @ s.X.T
    return {
        "Omega = M": Omega - s.Phi,
        "omega = m": s.X.T @ flow.Xdot - s.X.T @ s.Phi @ s.X,
        "(Euler*)": s.d(lambda t: t.Phi, flow) - comm(s.A, e @ e.T),
        "(Poisson) de_i/dt = Omega e_i": flow.Xdot - Omega @ s.X,
        "(mag2) de_n/dt = Omega e_n": s.d(last, flow) - Omega @ e,
        "(Poisson) with Omega = M keeps X^T X = I": (s.Phi @ s.X).T @ s.X + s.X.T @ (s.Phi @ s.X),
    }


@claim("ym-reduced-neumann", paper=("YM", "Euler**", "mag0", "iden1"), unlabelled=("Theorem 9.2",), kind="id", sizes=ON_V_NN1,
       statement=r"T^*V_{n,n-1}/SO(n-1)\cong so(n)\times S^{n-1}:\quad \dot\Omega=[A,e_n\otimes e_n],\quad \dot e_n=\Omega e_n,"
                 r"\quad \Omega=\Phi,\ e_n\otimes e_n=\mathbf I_n-XX^T")
def reduced_neumann_is_euler_star_star(s):
    """Proposition YM (i): the normal-metric Neumann flow (N0_XP2) on T*V_{n,n−1} (the Dirac flow of H_neum,0) reduces by the right SO(n−1) action to (Euler**) on so(n) × S^{n−1}: (Ω, e_n⊗e_n) = (Φ, I − XXᵀ) are invariant (e_n⊗e_n = I − XXᵀ by (iden1), see clebsch-perelomov-hamiltonian; it is the projector orthogonal to e₁, …, e_{n−1}), and Ω̇ = [A, e_n⊗e_n], d(e_n⊗e_n)/dt = [Ω, e_n⊗e_n] (equivalent to ė_n = Ωe_n for a unit e_n), equations that keep Ω skew and e_n⊗e_n a projector; the identities hold for every r, so the dimension-free method proves them for all n, r."""
    flow = s.dirac_flow(H_neumann_normal)
    N = s.In - s.X @ s.X.T
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    return {
        "e_n (x) e_n projector": N @ N - N,
        "e_n orthogonal to e_1..e_{n-1}": N @ s.X,
        "Omega, e_n (x) e_n right-invariant": [s.d(lambda t: t.Phi, right), s.d(lambda t: t.X @ t.X.T, right)],
        "(Euler**) dOmega/dt = [A, e_n (x) e_n]": s.d(lambda t: t.Phi, flow) - comm(s.A, N),
        "(Euler**) de_n/dt = Omega e_n": s.d(lambda t: t.In - t.X @ t.X.T, flow) - comm(s.Phi, N),
        "(Euler**) keeps Omega skew": comm(s.A, N) + comm(s.A, N).T,
        "(Euler**) keeps e_n (x) e_n a projector": comm(s.Phi, N) @ N + N @ comm(s.Phi, N) - comm(s.Phi, N),
    }


@claim("ym-charge", paper=("YM", "mag6", "mag0"), unlabelled=("Theorem 9.2",), kind="id", sizes=ON_V_NN1,
       statement=r"F_\Omega=\pr_{e_n^\perp}(\Omega)=X\Psi X^T,\quad X^TF_\Omega X=\Psi:\quad "
                 r"(F_\Omega,e_n,\dot e_n)\in\mathcal O_\eta\times_sTS^{n-1}\ \text{on}\ \Psi^{-1}(\mathcal O_\eta)")
def yang_mills_field_lies_on_the_orbit_of_the_charge(s):
    """On T*V_{n,n−1} (Ω = Φ, e_n⊗e_n = I − XXᵀ), the Yang–Mills field F_Ω = pr_{e_n⊥}(Ω) is XΨXᵀ, the momentum Ψ of the right SO(n−1) action carried to e_n⊥ by X, so on Ψ⁻¹(𝒪_η) it ranges over the orbit 𝒪_η (the charge type), and it vanishes on Ψ⁻¹(0), where (mag6) is the Neumann system on the sphere."""
    N = s.In - s.X @ s.X.T
    Omega = s.Phi
    F = Omega - (Omega @ N + N @ Omega)
    return {
        "F_Omega = X Psi X^T": F - s.X @ s.Psi @ s.X.T,
        "X^T F_Omega X = Psi": s.X.T @ F @ s.X - s.Psi,
        "F_Omega annihilates e_n": F @ N,
    }


def pr_e(xi, e):
    """pr_{e_n}(ξ) = ξe_n⊗e_n + e_n⊗e_nξ."""
    return xi @ e @ e.T + e @ e.T @ xi


@claim("ym-second-derivative", paper=("YM", "mag6", "mag3", "OD"), kind="id", sizes=ON_SO_N,
       statement=r"\ddot e_n=Ae_n-\big((e_n,Ae_n)+(\dot e_n,\dot e_n)\big)e_n+F_\Omega\dot e_n,\quad "
                 r"F_\Omega=\pr_{e_n^\perp}(\Omega)=\Omega-\Phi(e_n,\dot e_n),\quad "
                 r"\pr_{e_n}(\Omega)=\dot e_n\wedge e_n=\Phi(e_n,\dot e_n)")
def ym_second_derivative(s):
    """Proposition YM (ii): along the flow of H_CP, the second derivative of e_n is (mag6) with the Yang–Mills term F_{Ω}ė_n, F_Ω = pr_{e_n⊥}(Ω) = Ω − ė_n∧e_n, an equation that keeps TS^{n−1}; (mag3) pr_{e_n}(Ω) = ė_n∧e_n, pr_{e_n} is the orthogonal projection of (OD) (idempotent, ⟨pr_{e_n}ξ, pr_{e_n⊥}ζ⟩ = 0, pr_{e_n⊥}ξ annihilates e_n), ė_n = pr_{e_n}(Ω)e_n, and the steps of the proof hold."""
    flow = s.dirac_flow(H_CP)
    e = last(s)
    Omega = s.Phi
    edot = Omega @ e
    edd = s.d(lambda t: t.Phi @ last(t), flow)        # ė_n = Ωe_n = Φe_n on T*SO(n) (Poisson)
    F = Omega - wedge(edot, e)
    xi, zeta = s.xi, s.zeta
    return {
        "de_n/dt = Omega e_n": s.d(last, flow) - edot,
        "(mag6)": edd - (s.A @ e - (dot(s, e, s.A @ e) + dot(s, edot, edot)) * e + F @ edot),
        "(mag6) keeps TS^{n-1}: d/dt (e_n, de_n/dt) = 0": dot(s, edot, edot)
        + dot(s, e, s.A @ e - (dot(s, e, s.A @ e) + dot(s, edot, edot)) * e + F @ edot),
        "(mag3) pr_e(Omega) = de_n/dt ^ e_n": pr_e(Omega, e) - wedge(edot, e),
        "F_Omega = pr_perp(Omega)": F - (Omega - pr_e(Omega, e)),
        "de_n/dt = pr_e(Omega) e_n": pr_e(Omega, e) @ e - edot,
        "(OD) pr_e idempotent": pr_e(pr_e(xi, e), e) - pr_e(xi, e),
        "(OD) orthogonal": s.killing(pr_e(xi, e), zeta - pr_e(zeta, e)),
        "(OD) pr_perp(xi) e_n = 0": (xi - pr_e(xi, e)) @ e,
        "proof: dOmega/dt e_n = (A e_n (x) e_n - e_n (x) e_n A) e_n": s.d(lambda t: t.Phi, flow) @ e
        - (s.A @ e @ e.T - e @ e.T @ s.A) @ e,
        "proof: pr_e(Omega) de_n/dt = (de_n/dt ^ e_n) de_n/dt": pr_e(Omega, e) @ edot - wedge(edot, e) @ edot,
    }


# -- the n = 3 monopole remark ------------------------------------------------------------------------

def cross(s, a, b):
    """a × b for columns a, b of ℝ³ (read from coordinates)."""
    x = [a[i, 0] for i in range(3)]
    y = [b[i, 0] for i in range(3)]
    return s.mat([[x[1] * y[2] - x[2] * y[1]], [x[2] * y[0] - x[0] * y[2]], [x[0] * y[1] - x[1] * y[0]]], ("n", "?"))


def e3_of(s):
    """(iden1) for n = 3: e₃ = e₁ × e₂, so that (e₁, e₂, e₃) ∈ SO(3)."""
    return cross(s, col(s, 0), col(s, 1))


def monopole_terms(s):
    """Ω = Φ, e₃ = e₁ × e₂, ė₃ (derived along the normal Neumann flow on V_{3,2}), F_Ω, ε = Ψ₁₂, ë₃."""
    flow = s.dirac_flow(H_neumann_normal)
    e3 = e3_of(s)
    Omega = s.Phi
    e3dot = Omega @ e3
    F = Omega - wedge(e3dot, e3)
    eps = s.Psi[0, 1]                               # η = Ψ = εE₁∧E₂
    e3dd = s.d(lambda t: t.Phi @ e3_of(t), flow)    # ė₃ = Ωe₃ (checked below)
    return flow, e3, e3dot, F, eps, e3dd


def monopole_identities(s, flow, e3, e3dot, F, eps, e3dd):
    """What the remark rests on: e₃ completes (e₁, e₂) to SO(3), ė₃ = Ωe₃ along the derived flow, the
    Yang–Mills field is F_Ω = XΨXᵀ = εe₁∧e₂, and (mag6) holds at n = 3 (so the monopole equation is
    (mag6) with F_Ωė₃ replaced by the Lorentz force)."""
    A = s.A
    return {
        "e₃ ⊗ e₃ − (I − XXᵀ)": e3 @ e3.T - (s.In - s.X @ s.X.T),
        "d(e₁ × e₂)/dt − Ωe₃": s.d(e3_of, flow) - e3dot,
        "F_Ω − ε e₁ ∧ e₂": F - eps * wedge(col(s, 0), col(s, 1)),
        "(4) §9 at n = 3": e3dd - (A @ e3 - (dot(s, e3, A @ e3) + dot(s, e3dot, e3dot)) * e3 + F @ e3dot),
    }


def monopole_checks(s, sign):
    """The remark with the Lorentz force sign·ε e₃ × ė₃ (sign = 1: as printed)."""
    flow, e3, e3dot, F, eps, e3dd = monopole_terms(s)
    checks = monopole_identities(s, flow, e3, e3dot, F, eps, e3dd)
    checks["F_Ω ė₃ − ε e₃ × ė₃"] = F @ e3dot - sign * eps * cross(s, e3, e3dot)
    return checks


@claim("ym-monopole", nature="formula", paper=("YM", "mag6"), kind="id",
       sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, stated_n_max=3, condition="n = 3, r = 2"),
       equivariance="e_3 = e_1 x e_2 is read from coordinates, but (g e_1) x (g e_2) = det(g) g (e_1 x e_2) for g "
                    "in O(3), so under (X, P, A) -> (gX, gP, gAg^T) every residual becomes g R g^T (those even in "
                    "e_3) or det(g) g R (those odd in e_3: the cross products, e_3 and its derivatives); each vanishes "
                    "everywhere iff it vanishes at X0 for all P and A",
       fails_at=lambda n, r: True,
       place="the paragraph after Proposition 9.1, on the case n = 3, r = 2",
       erratum="""The paragraph after Proposition 9.1, on the case n = 3, r = 2: with η = Ψ = ε E₁ ∧ E₂
       (Ψ = XᵀP − PᵀX), e₃ = e₁ × e₂ by (3) §7 and so(3) identified with (ℝ³, ×) as Lie algebras,
       F_Ω = XΨXᵀ = ε e₁ ∧ e₂ = −ε ê₃, so the Lorentz force is F_Ω ė₃ = −ε e₃ × ė₃, not +ε e₃ × ė₃: the
       monopole equation holds as ë₃ = Ae₃ − ((e₃, Ae₃) + (ė₃, ė₃)) e₃ − ε e₃ × ė₃ (equivalently, the printed
       sign with η = −ε E₁ ∧ E₂, a monopole of the opposite charge).  (4) §9 itself holds.""",
       statement=r"n=3,\ \eta=\varepsilon E_1\wedge E_2:\quad \ddot e_3=Ae_3-\big((e_3,Ae_3)+(\dot e_3,\dot e_3)\big)e_3"
                 r"+\varepsilon\,e_3\times\dot e_3,\quad F_\Omega\dot e_3=\varepsilon\,e_3\times\dot e_3")
def monopole_form(s):
    """The n = 3 case of Proposition YM: for the normal Neumann flow on V_{3,2} with Ψ = εE₁∧E₂, under so(3) ≅ (ℝ³, ×) and e₃ = e₁ × e₂, the Yang–Mills term of (mag6) is the Lorentz force of a magnetic monopole, F_{Ω}ė₃ = εe₃ × ė₃, so that (mag6), checked here at n = 3, becomes the printed monopole equation."""
    flow, e3, e3dot, F, eps, e3dd = monopole_terms(s)
    checks = monopole_identities(s, flow, e3, e3dot, F, eps, e3dd)
    checks["F_Ω ė₃ − ε e₃ × ė₃"] = F @ e3dot - eps * cross(s, e3, e3dot)
    return checks


@monopole_form.claim.correction("the Lorentz force with the opposite sign: F_Ω ė₃ = −ε e₃ × ė₃")
def monopole_form_corrected(s):
    return monopole_checks(s, -1)


# -- the symmetric Clebsch–Perelomov–Bogoyavlenski body ---------------------------------------------------

def H_CPB(s, k):
    """H_CPB = ½⟨M, M⟩ + ½Σ_{i≤k}(e_i, Ae_i) = ½⟨M, M⟩ + ½tr(D_k𝒳ᵀA𝒳) on T*SO(n)."""
    return s.killing(s.Phi, s.Phi) / 2 + s.tr(projector(s, k) @ s.X.T @ s.A @ s.X) / 2


def cpb_hamiltonians(s):
    """H_CPB for k = 1, ..., n − 1 (k = n: a constant potential)."""
    return [(k, lambda t, k=k: H_CPB(t, k)) for k in twisted.column_splittings(s)]


def H_CPB_blocks(s):
    """H_CPB = ½⟨M, M⟩ + ½tr(D𝒳ᵀA𝒳) for the projector D of the first block of ℝⁿ = ℝᵏ ⊕ ℝⁿ⁻ᵏ (k = ⌈n/2⌉ at
    fixed sizes; dimension-free, D any orthogonal projector: every k at once)."""
    return s.killing(s.Phi, s.Phi) / 2 + s.tr(twisted.block_projector(s, 0) @ s.X.T @ s.A @ s.X) / 2


@claim("cpb-euler", paper=("Euler", "CPB", "Poisson"), kind="id", sizes=ON_SO_N,
       statement=r"H_{CPB}=\tfrac12\langle M,M\rangle+\tfrac12\sum_{i=1}^r(e_i,Ae_i):\quad "
                 r"\dot\Omega=[e_1\otimes e_1+\dots+e_r\otimes e_r,A],\ \dot e_i=\Omega e_i;\quad "
                 r"h=\Omega,\ v=\textstyle\sum_{i\le r}e_i\otimes e_i:\ \dot h=[v,A],\ \dot v=[h,v]")
def cpb_euler(s):
    """For every r < n, the Dirac flow of the symmetric Clebsch–Perelomov–Bogoyavlenski Hamiltonian H_CPB on T*SO(n) has Ω = M and is the Euler–Poincaré equation (Euler) with the Poisson equations (Poisson), closed in h = Ω, v = Σ_{i≤r} e_i⊗e_i as (CPB) (which keeps h skew and v a projector), with H_CPB = ½⟨h, h⟩ − ⟨A, v⟩.  Σ_{i≤r} e_i⊗e_i = 𝒳D𝒳ᵀ with D the projector of the first block of a splitting of ℝⁿ (r = ⌈n/2⌉ columns at fixed sizes; dimension-free, every splitting, so every r, at once)."""
    H = H_CPB_blocks
    flow = s.dirac_flow(H)
    D = twisted.block_projector(s, 0)
    v = s.X @ D @ s.X.T
    Omega = flow.Xdot @ s.X.T
    return {
        "Omega = M": Omega - s.Phi,
        "(Poisson)": flow.Xdot - Omega @ s.X,
        "(Euler)": s.d(lambda t: t.Phi, flow) - comm(v, s.A),
        "(CPB) dv/dt = [h, v]": s.d(lambda t: t.X @ twisted.block_projector(t, 0) @ t.X.T, flow) - comm(s.Phi, v),
        "H_CPB = 1/2<h, h> - <A, v>": H(s) - (s.killing(s.Phi, s.Phi) / 2 - s.killing(s.A, v)),
        "(CPB) keeps v a projector and h skew": [
            comm(s.Phi, v) @ v + v @ comm(s.Phi, v) - comm(s.Phi, v), comm(v, s.A) + comm(v, s.A).T],
    }


@claim("cpb-right-momentum", paper=("Euler", "CPB"), kind="pb", sizes=ON_SO_N,
       statement=r"\Psi=\Psi_{so(r)}+\Psi_{so(n-r)},\ \Psi_{so(r)}=\pr_{so(r)}(\mathcal X^{-1}\Omega\mathcal X),\ "
                 r"\Psi_{so(n-r)}=\pr_{so(n-r)}(\mathcal X^{-1}\Omega\mathcal X):\quad \tfrac{d}{dt}\Psi_{so(r)}=\tfrac{d}{dt}\Psi_{so(n-r)}=0")
def cpb_right_momentum(s):
    """For every r < n, H_CPB is right SO(r) × SO(n−r)-invariant and the components Ψ_so(r), Ψ_so(n−r) of the body angular momentum 𝒳⁻¹Ω𝒳 = 𝒳ᵀM𝒳 are conserved by its flow.  so(r) ⊕ so(n−r) are the blocks D·D, C·C of the projectors D, C of a splitting of ℝⁿ (r = ⌈n/2⌉ at fixed sizes; dimension-free, any two orthogonal blocks, so every r, at once)."""
    H = H_CPB_blocks
    flow = s.dirac_flow(H)
    D, C = twisted.block_projector(s, 0), twisted.block_projector(s, 1)
    eta = D @ s.eta @ D + C @ s.eta @ C
    body = lambda t: t.X.T @ t.Phi @ t.X      # 𝒳⁻¹Ω𝒳 with Ω = M and 𝒳⁻¹ = 𝒳ᵀ  # noqa: E731
    block = lambda t, i: twisted.block_projector(t, i) @ body(t) @ twisted.block_projector(t, i)  # noqa: E731
    return {
        "H_CPB right SO(r) x SO(n-r)-invariant": s.d(H, {"X": s.X @ eta, "P": s.P @ eta}),
        "dPsi_so(r)/dt": s.d(lambda t: block(t, 0), flow),
        "dPsi_so(n-r)/dt": s.d(lambda t: block(t, 1), flow),
    }


# -- the reduction of the CPB body to V(n, r) ------------------------------------------------------------

def body_block_removed(s, k, block):
    """A point of T*SO(n) where one block of the body momentum m = 𝒳ᵀM𝒳 = 2𝒳ᵀ𝒫 vanishes: Ψ_so(r) = 0
    (block "so(r)", the first k columns) or Ψ_so(n−r) = 0 (block "so(n-r)")."""
    D = projector(s, k)
    Z = D if block == "so(r)" else s.Ir - D
    W = s.X.T @ s.P
    return twisted.at_point(s, s.X, s.P - s.X @ (Z @ W @ Z))


def cpb_reduction_checks(s, block):
    """Along the flow of H_CPB (first k columns), at a point where the given block of the body momentum
    vanishes, the image (X_r, P_r) in T*V(n, r), X_r = (e_1, ..., e_r), P_r = MX_r − ½X_rX_rᵀMX_r, moves by
    the normal-metric Neumann flow (N0_XP2)."""
    checks = {}
    for k in twisted.column_splittings(s):
        if s.r - k < 2:
            continue        # so(n - r) = 0: nothing to reduce
        h = body_block_removed(s, k, block)
        flow = h.dirac_flow(lambda t, k=k: H_CPB(t, k))
        D = projector(h, k)
        Z = D if block == "so(r)" else h.Ir - D
        image = lambda t, k=k: (t.X @ twisted.first_basis_vectors(t, k),
                                t.Phi @ t.X @ twisted.first_basis_vectors(t, k)
                                - t.X @ twisted.first_basis_vectors(t, k) @ twisted.first_basis_vectors(t, k).T
                                @ t.X.T @ t.Phi @ t.X @ twisted.first_basis_vectors(t, k) / 2)
        Xr, Pr = image(h)
        target = flow_N0_at(h, Xr, Pr)
        checks[f"the block {block.replace('-', ' − ')} of the body momentum vanishes (r = {k})"] = Z @ h.X.T @ h.Phi @ h.X @ Z
        checks[f"dXᵣ/dt − Ẋᵣ by (4) §5 (r = {k})"] = h.d(lambda t, image=image: image(t)[0], flow) - target["X"]
        checks[f"dPᵣ/dt − Ṗᵣ by (4) §5 (r = {k})"] = h.d(lambda t, image=image: image(t)[1], flow) - target["P"]
    return checks


@claim("cpb-reduction-stiefel", nature="statement", paper=("Euler", "Poisson", "CPB", "N0_XP2"), kind="id",
       sizes=admissible(n_max=5, n_min=3, where=lambda n, r: r == n, condition="r = n >= 3: T*SO(n), n - r >= 2"),
       fails_at=lambda n, r: True,
       place="the last sentence of the paragraph “Symmetric Clebsch–Perelomov–Bogoyavlenski rigid body systems” in §9",
       erratum="""The paragraph on the symmetric Clebsch–Perelomov–Bogoyavlenski bodies says that for
       eta_so(r) = 0 the reduction of (10) §9 and (7) §9 gives the Neumann system with the normal metric on
       V_{n,r}.  The reduction to V_{n,r} is the one by SO(n − r), and the condition is on its momentum:
       at a point where Psi_so(r) = 0 but Psi_so(n−r) ≠ 0 (possible when n − r ≥ 2) the image (X_r, P_r) in
       T*V_{n,r} of the reduction, X_r = (e_1, …, e_r) and P_r = MX_r − ½X_r X_r^T MX_r (the covector with Φ = M
       where Psi_so(n−r) = 0), does not follow the Neumann flow (4) §5 of the normal metric (the Yang–Mills field of
       SO(n − r) acts); it does where Psi_so(n−r) = 0.  Corrected: “if eta_so(n−r) = 0 (eta_so(r) = eta_so(n−r) = 0),
       we get the Neumann system with the normal metric on V_{n,r} (respectively, the Neumann system on G_{n,r})”.
       The sizes (n, n) of this claim are those of the body's T*SO(n) (the component det X = 1 of T*V_{n,n} = T*O(n); both components are computed), not the paper's (n, r): a run at
       (n, n) checks the printed condition and the correction at each of the paper's r = 1, …, n − 2 (the image of
       the first r columns in T*V_{n,r}), so at (3,3), the size of the witness, at r = 1 only.""",
       statement=r"\eta_{so(r)}=0:\ \text{the reduction of (10), (7) of Section 9 is the Neumann system with the normal "
                 r"metric on }V_{n,r}")
def cpb_reduces_to_the_normal_neumann_system(s):
    """The symmetric CPB body reduced with η_so(r) = 0 is, as the paper says, the Neumann system with the normal metric on V_{n,r}: at a point of T*SO(n) where the so(r) block of the body momentum vanishes, the first r columns and P_r = MX_r − ½XᵣXᵣᵀMX_r (the covector with Φ = M when Ψ_so(n−r) = 0) move by (N0_XP2), for every r ≤ n − 2."""
    return cpb_reduction_checks(s, "so(r)")


@cpb_reduces_to_the_normal_neumann_system.claim.correction("η_so(n−r) = 0 in place of η_so(r) = 0")
def cpb_reduces_to_the_normal_neumann_system_corrected(s):
    return cpb_reduction_checks(s, "so(n-r)")


# -- the spectral invariants with Φ_ε (the theorem on complete integrability) --------------------------------

#: the powers k of the spectral invariants tr 𝓛(λ)^k checked (as in §5)
POWERS = (1, 2, 3)


def spectral_checks(s, momentum, H, F=None):
    """tr(λΦ' + XXᵀ − λ²A)^k (Φ' the twisted momentum map) are integrals of the twisted flow of H and
    Poisson-commute for two values λ, μ of the spectral parameter, for the twisted bracket."""
    def L_at(t, mu):
        return mu * momentum(t) + t.X @ t.X.T - mu * mu * t.A

    def power_trace(t, M, k):
        acc = M
        for _ in range(k - 1):
            acc = acc @ M
        return t.tr(acc)
    flow = twisted.flow(s, H, F=F)
    checks = {}
    for k in POWERS:
        checks[f"d tr L(lambda)^{k}/dt"] = s.d(lambda t, k=k: power_trace(t, L_at(t, t.lam), k), flow)
    for k in POWERS:
        for m in POWERS:
            if m < k:
                continue
            checks[f"{{tr L(lambda)^{k}, tr L(mu)^{m}}}_eps"] = twisted.bracket(
                s, lambda t, k=k: power_trace(t, L_at(t, t.lam), k),
                lambda t, m=m: power_trace(t, L_at(t, t.scalar("mu")), m), F=F)
    return checks


@claim("magnetic-spectral-invariants", paper=("perelomov", "mag-euk", "mag-nor", "mag-mom-stief"), unlabelled=("Theorem 9.5",), kind="pb",
       sizes=ON_V_N2,
       statement=r"\{\tr\mathcal L_\epsilon(\lambda)^k,H\}_\epsilon=0,\ \{\tr\mathcal L_\epsilon(\lambda)^k,"
                 r"\tr\mathcal L_\epsilon(\mu)^m\}_\epsilon=0,\quad \mathcal L_\epsilon=\lambda\Phi_\epsilon+XX^T-\lambda^2A,\ k,m=1,2,3")
def magnetic_spectral_invariants(s):
    """The functions tr(λΦ_ε + XXᵀ − λ²A)^k, k = 1, 2, 3, the integrals of the theorem on the complete integrability of the magnetic Neumann systems, are conserved by both (mag-euk) and (mag-nor) and Poisson-commute for the twisted bracket."""
    checks = {}
    for name, H in MAGNETIC_HAMILTONIANS:
        for key, value in spectral_checks(s, Phi_eps, H).items():
            if key.startswith("d tr") or name == "mag-euk":   # the brackets do not depend on H
                checks[f"{key} ({name})" if key.startswith("d tr") else key] = value
    return checks


@claim("magnetic-spectral-invariants-any-rank", paper=("perelomov", "mag-mom-stief", "twisted"), unlabelled=("Theorem 9.5",), kind="pb",
       sizes=admissible(n_max=4),
       statement=r"\{\tr\mathcal L_F(\lambda)^k,H_{neum,\kappa}\}_F=0,\ \{\tr\mathcal L_F(\lambda)^k,"
                 r"\tr\mathcal L_F(\mu)^m\}_F=0,\quad \mathcal L_F=\lambda\Phi_F+XX^T-\lambda^2A,\ k,m=1,2,3")
def magnetic_spectral_invariants_every_rank(s):
    """For every n, r, κ and generic constant F ∈ so(r), the functions tr(λΦ_F + XXᵀ − λ²A)^k, k = 1, 2, 3, are integrals of the flow of H_neum,κ for the twisted form ω_F and Poisson-commute for its bracket."""
    return spectral_checks(s, Phi_F, H_neumann_kappa, F=s.eta)
