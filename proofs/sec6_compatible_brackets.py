"""§6 Compatible Poisson brackets and integrability: the pencil Λ1, Λ2 on gl(n), the map Θ = Φ + XXᵀ, the Casimirs and the integrable families of the section."""
from __future__ import annotations

from stiefelsym import Rank, admissible, claim, comm, twisted
from stiefelsym.brackets import (SO_R, MatrixFunction, casimir_residual, compatibility, dirac, lambda1, lambda2,
                                 lie_poisson, linear, pencil, poisson_checks, poisson_map_residual, quadratic,
                                 skew, sym, trace_power)

from .sec2_hamiltonian_flows import wedge_basis

SECTION = "6"

#: the powers k of the trace functions tr(·)^k checked (the paper: k = 1, ..., n or 1, ..., r)
POWERS = (1, 2, 3)


def power_trace(s, M, k):
    """tr M^k."""
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return s.tr(acc)


# -- the map Θ and the functions of the section ------------------------------------------

def Theta_at(X, P):
    """Θ = Φ + XXᵀ = Σ p_i ∧ e_i + Σ e_i ⊗ e_i at the point (X, P)."""
    return P @ X.T - X @ P.T + X @ X.T


def Theta(t):
    """Θ = Φ + XXᵀ at the point of the scene."""
    return Theta_at(t.X, t.P)


def central_function(s, x, lam, k, A=None):
    """(central): tr(λh + v − λ²A)^k with x = h + v, h ∈ so(n), v ∈ Sym(n)."""
    A = s.A if A is None else A
    return power_trace(s, lam * skew(x) + sym(x) - lam * lam * A, k)


def central(k, lam, shift_A=True):
    """(central) as a function on gl(n) with its gradient: tr(λh + v − λ²A)^k (λ = lam(s))."""
    if shift_A:
        return trace_power(k, so_scale=lam, shift=lambda s: -(lam(s) * lam(s)) * s.A, name=f"tr(λh+v-λ²A)^{k}")
    return trace_power(k, so_scale=lam, name=f"tr(λh+v)^{k}")


def perelomov(t, lam, k):
    """(perelomov): tr(λ(PXᵀ − XPᵀ) + XXᵀ − λ²A)^k."""
    return power_trace(t, lam * (t.P @ t.X.T - t.X @ t.P.T) + t.X @ t.X.T - lam * lam * t.A, k)


def FF(t, lam, k):
    """(FF): tr(λ(PXᵀ − XPᵀ) + XXᵀ)^k (A = 0)."""
    return power_trace(t, lam * (t.P @ t.X.T - t.X @ t.P.T) + t.X @ t.X.T, k)


def mu(t):
    """A second value μ of the spectral parameter."""
    return t.scalar("mu")


def Phi_xi(t):
    """Φ_ξ = <Φ, ξ>."""
    return t.killing(t.Phi, t.xi)


def Psi_eta(t):
    """Ψ_η = <Ψ, η>."""
    return t.killing(t.Psi, t.eta)


def H_jensen(t):
    """(EM) H_κ = ½<Φ, Φ> + κ/2 <Ψ, Ψ>."""
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2


def H_neum0(t):
    """(neumann) with κ = 0: ½tr(PᵀP) − ½tr((XᵀP)²) + ½tr(XᵀAX)."""
    XtP = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(XtP @ XtP) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_neum_kappa(t):
    """(neumann): ½tr(PᵀP) − (½ + κ)tr((XᵀP)²) + ½tr(XᵀAX)."""
    XtP = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(XtP @ XtP) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_cpb_value(s, x):
    """The Hamiltonian of the Remark after Theorem NEUMANN: H = ½<h, h> − <A, v>, x = h + v."""
    return s.killing(skew(x), skew(x)) / 2 - s.killing(s.A, sym(x))


#: H = ½<h, h> − <A, v> as a function on gl(n) with its gradient ∇H = h − A
H_CPB = quadratic(lambda s, x: skew(x), "½<h,h>") + linear(lambda s: -s.A, "-<A,v>")


def gl_generic(s, name):
    """A generic n x n matrix (an element, or a covector, of gl(n))."""
    return s.generic(name, "n", "n")


# -- the Lie algebra gl(n) = so(n) + Sym(n) and the pencil --------------------------------

@claim("symmetric-pair", paper=("symmetric-pair", "killing"), kind="id",
       statement=r"[so(n),Sym(n)]\subset Sym(n),\quad [Sym(n),Sym(n)]\subset so(n),\quad "
                 r"\langle so(n),Sym(n)\rangle=0,\quad \langle\xi,\xi\rangle=\tfrac12\tr(\xi^T\xi),\ "
                 r"\langle\eta,\eta\rangle=-\tfrac12\tr(\eta^T\eta)")
def symmetric_pair(s):
    """(symmetric-pair): gl(n) = so(n) + Sym(n) is a symmetric pair, the decomposition is orthogonal for <,>, and <,> is positive definite on so(n) (½ the sum of squares of the entries) and negative definite on Sym(n)."""
    xi = s.xi
    eta = gl_generic(s, "S") + gl_generic(s, "S").T
    theta = gl_generic(s, "T") + gl_generic(s, "T").T
    C = comm(xi, eta)
    D = comm(eta, theta)
    return {
        "[xi, eta] symmetric": C - C.T,
        "[eta, theta] skew": D + D.T,
        "<xi, eta>": s.killing(xi, eta),
        "<xi, xi> = 1/2 tr(xi^T xi)": s.killing(xi, xi) - s.tr(xi.T @ xi) / 2,
        "<eta, eta> = -1/2 tr(eta^T eta)": s.killing(eta, eta) + s.tr(eta.T @ eta) / 2,
    }


@claim("lambda12-compatible", paper=("LAMBDA12",), kind="pb", exact_max_n=4,
       equivariance="no point of T*V enters: the tensors are evaluated at a generic x in gl(n) with generic covectors, in a basis of gl(n)",
       statement=r"\Lambda_1(\xi+\eta,\zeta+\theta)|_x=\langle x,[\xi,\zeta]+[\xi,\theta]+[\eta,\zeta]\rangle,\ "
                 r"\Lambda_2(\xi+\eta,\zeta+\theta)|_x=\langle x-A,[\xi+\eta,\zeta+\theta]\rangle:\quad "
                 r"[\Lambda_1,\Lambda_1]=[\Lambda_2,\Lambda_2]=[\Lambda_1,\Lambda_2]=0")
def pencil_is_poisson_and_compatible(s):
    """(LAMBDA12): Λ1 and Λ2 on gl(n) are bivectors (antisymmetric, and additive in a covector) and satisfy the Jacobi identity, and so does Λ1 + Λ2, so they are compatible (Jacobi identity for linear functions with generic covectors at a generic point, the derivative in x taken exactly)."""
    checks = {}
    checks.update(poisson_checks(s, lambda1(), "Lambda1"))
    checks.update(poisson_checks(s, lambda2(), "Lambda2"))
    checks.update(compatibility(s, lambda1(), lambda2(), "pencil"))
    return checks


@claim("pencil-casimirs", paper=("central", "LAMBDA12"), kind="pb", exact_max_n=7,
       statement=r"\Lambda_{\lambda_1,\lambda_2}\big(\nabla\tr(\sqrt{\tfrac{\lambda_2}{\lambda_1+\lambda_2}}h+v-"
                 r"\tfrac{\lambda_2}{\lambda_1+\lambda_2}A)^k,\cdot\big)=0,\ \Lambda_{\lambda_1,\lambda_2}\cong gl(n);\quad "
                 r"\{\tr(\lambda h+v-\lambda^2A)^k,\tr(\mu h+v-\mu^2A)^m\}_{\Lambda_{\lambda_1,\lambda_2}}=0,\ k,m\le3")
def pencil_casimirs_commute(s):
    """The functions tr(√(λ₂/(λ₁+λ₂))h + v − λ₂/(λ₁+λ₂)A)^k are Casimirs of Λ_{λ1,λ2} = λ₁Λ₁ + λ₂Λ₂ (written with λ₁ = σ(1 − c²), λ₂ = σc², which covers every λ₂/(λ₁+λ₂) > 0), because x ↦ ch + v − c²A maps Λ_{λ1,λ2} to σc times the Lie–Poisson bracket of gl(n), and the functions (central) tr(λh + v − λ²A)^k commute for every bracket of the pencil (k, m = 1, 2, 3, at a generic point of gl(n))."""
    c = lambda t: t.scalar("c")                                      # noqa: E731
    sigma = lambda t: t.scalar("sigma")                              # noqa: E731
    T_c = pencil(lambda t: sigma(t) * (t.q(1) - c(t) * c(t)), lambda t: sigma(t) * c(t) * c(t))
    T = pencil(lambda t: t.scalar("lambda_1"), lambda t: t.scalar("lambda_2"))
    x, b = gl_generic(s, "x"), gl_generic(s, "b")
    checks = {}
    for k in POWERS:
        checks[f"Lambda(grad f_{k}, b): f_{k} a Casimir"] = casimir_residual(s, T_c, central(k, c), x, b)
    for k in POWERS:
        for m in POWERS:
            if m >= k:
                checks[f"{{tr L(lambda)^{k}, tr L(mu)^{m}}} in the pencil"] = T.bracket(
                    s, central(k, lambda t: t.lam), central(m, mu), x)
    # why: ψ(x) = ch + v − c²A maps Λ_{λ1,λ2} to (λ₁+λ₂)c times the Lie–Poisson bracket of gl(n)
    a = gl_generic(s, "a")
    lin_a = MatrixFunction(lambda t, y: t.killing(psi_pencil(t, y, c(t)), a),
                           lambda t, y: skew(a) * c(t) + sym(a), "<psi, a>")
    lin_b = MatrixFunction(lambda t, y: t.killing(psi_pencil(t, y, c(t)), b),
                           lambda t, y: skew(b) * c(t) + sym(b), "<psi, b>")
    checks["{<psi, a>, <psi, b>} - (lambda_1 + lambda_2) c <psi, [a, b]>"] = (
        T_c.bracket(s, lin_a, lin_b, x) - sigma(s) * c(s) * s.killing(psi_pencil(s, x, c(s)), comm(a, b)))
    return checks


def psi_pencil(s, x, c):
    """ψ(x) = ch + v − c²A (x = h + v): the isomorphism of (gl(n), Λ_{λ1,λ2}), c² = λ₂/(λ₁+λ₂), with
    gl(n) and its Lie–Poisson bracket times (λ₁+λ₂)c, which carries the Casimirs tr y^k to (central)."""
    return skew(x) * c + sym(x) - (c * c) * s.A


# -- the Poisson map Θ ------------------------------------------------------------------

@claim("theta-poisson-map", paper=("LAMBDA12", "right_action", "perelomov", "central"), kind="pb",
       statement=r"\{\langle\Theta,a\rangle,\langle\Theta,b\rangle\}=\Lambda_1(a,b)|_{\Theta},\ \Theta=\Phi+XX^T;\quad "
                 r"\Theta(XQ,PQ)=\Theta(X,P)=\Theta(-X,-P);\quad \mathfrak F=\Theta^*\mathcal F")
def theta_is_a_poisson_map(s):
    """Θ = Φ + XXᵀ is a Poisson map from (T*V, Dirac bracket) to (gl(n), Λ1) (linear functions with generic covectors a, b suffice), invariant under the right SO(r) action and under (X, P) ↦ (−X, −P), and the integrals (perelomov) are the pull-backs Θ*𝓕 of the functions (central)."""
    a, b = (lambda t: gl_generic(t, "a")), (lambda t: gl_generic(t, "b"))
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    checks = {
        "{<Theta,a>, <Theta,b>} - Lambda1(a, b)|Theta": poisson_map_residual(s, dirac, Theta, lambda1(), a, b),
        "d Theta along (X eta, P eta)": s.d(Theta, right),
        "Theta(-X, -P) - Theta(X, P)": Theta_at(-s.X, -s.P) - Theta(s),
    }
    for k in POWERS:
        checks[f"perelomov_{k} - central_{k}(Theta)"] = perelomov(s, s.lam, k) - central_function(s, Theta(s), s.lam, k)
    return checks


@claim("theta-reflection", paper=("right_action", "REDUCED_BRACKET"), kind="id",
       statement=r"R=\mathrm{diag}(-1,1,\dots,1)\in O(r)\setminus SO(r):\quad \Theta(XR,PR)=\Theta(X,P),\quad "
                 r"\Psi(XR,PR)=R\Psi R")
def theta_is_invariant_under_a_reflection(s):
    """Θ = Φ + XXᵀ is invariant under (X, P) ↦ (XR, PR) for the reflection R = diag(−1, 1, …, 1) ∈ O(r) ∖ SO(r), which maps Ψ to RΨR: the ℤ₂ of the covering θ of §6 is O(r)/SO(r), acting on (T*V)/SO(r) by this reflection; (X, P) ↦ (−X, −P) is R = −Iᵣ, which lies in SO(r) when r is even."""
    r = s.r
    R = s.mat([[(s.q(-1) if i == 0 else s.q(1)) if i == j else s.q(0) for j in range(r)] for i in range(r)],
              ("r", "r"))
    XR, PR = s.X @ R, s.P @ R
    return {
        "R^T R - I": R.T @ R - s.Ir,
        "Theta(XR, PR) - Theta(X, P)": Theta_at(XR, PR) - Theta(s),
        "Psi(XR, PR) - R Psi R": XR.T @ PR - PR.T @ XR - R @ s.Psi @ R,
    }


def theta2_semidirect_bracket(s, a, b, mu_, Y):
    """{<Θ₂, a>, <Θ₂, b>} on (so(n) ⊕_ρ M_{n,r})* at (μ, Y) for Θ₂(μ, Y) = μ + YYᵀ: the Lie–Poisson
    bracket <μ, [α_a, α_b]> − tr(U_bᵀα_aY) + tr(U_aᵀα_bY) with the gradients α = skew(a) in so(n) and
    U = −sym(a)Y in M_{n,r} (trace pairing), the bracket of which Θ₁ = Φ + X is a realization
    ({<μ, α>, tr(UᵀY)} = −tr(UᵀαY), as {Φ_ξ, tr(UᵀX)} = −tr(UᵀξX))."""
    alpha_a, alpha_b = skew(a), skew(b)
    U_a, U_b = -(sym(a) @ Y), -(sym(b) @ Y)
    return (s.killing(mu_, comm(alpha_a, alpha_b)) - s.tr(U_b.T @ alpha_a @ Y) + s.tr(U_a.T @ alpha_b @ Y))


@claim("theta-factorization", paper=("LAMBDA12", "momentum_map"), kind="pb",
       statement=r"\Theta=\Theta_2\circ\Theta_1,\ \Theta_1=\Phi+X,\ \Theta_2(\xi,Y)=\xi+YY^T:\quad "
                 r"\{\Phi_\xi,\Phi_\zeta\}=\langle\Phi,[\xi,\zeta]\rangle,\ \{\Phi_\xi,\tr(U^TX)\}=-\tr(U^T\xi X),\ "
                 r"\{\tr(U^TX),\tr(V^TX)\}=0;\ \Theta_2\ \text{Poisson into}\ (so(n)\oplus_{\ad}Sym(n))^*")
def theta_is_a_composition_of_poisson_maps(s):
    """Θ = Θ₂∘Θ₁: Θ₁ = Φ + X satisfies the Lie–Poisson relations of the semi-direct product so(n) ⊕_ρ M_{n,r} for the Dirac bracket ({Φ_ξ, Φ_ζ} = Φ_{[ξ,ζ]}, {Φ_ξ, tr(UᵀX)} = −tr(UᵀξX), {tr(UᵀX), tr(VᵀX)} = 0), and Θ₂(μ, Y) = μ + YYᵀ maps that bracket to Λ₁ (at a generic (μ, Y), with generic covectors a, b of gl(n))."""
    U, V = s.generic("U", "n", "r"), s.generic("V", "n", "r")
    zeta = s.zeta
    a, b = gl_generic(s, "a"), gl_generic(s, "b")
    mu_, Y = s.xi, s.generic("Y", "n", "r")
    trUX = lambda t: t.tr(t.generic("U", "n", "r").T @ t.X)   # noqa: E731
    trVX = lambda t: t.tr(t.generic("V", "n", "r").T @ t.X)   # noqa: E731
    return {
        "{Phi_xi, Phi_zeta} - <Phi, [xi, zeta]>": s.bracket(Phi_xi, lambda t: t.killing(t.Phi, t.zeta))
        - s.killing(s.Phi, comm(s.xi, zeta)),
        "{Phi_xi, tr(U^T X)} + tr(U^T xi X)": s.bracket(Phi_xi, trUX) + s.tr(U.T @ s.xi @ s.X),
        "{tr(U^T X), tr(V^T X)}": s.bracket(trUX, trVX),
        "Theta_2 Poisson": theta2_semidirect_bracket(s, a, b, mu_, Y) - lambda1()(s, mu_ + Y @ Y.T, a, b),
        "Theta = Theta_2(Phi, X)": (s.Phi + s.X @ s.X.T) - Theta(s),
    }


# -- the reduced bracket and its Casimirs J_k ---------------------------------------------

def J(t, k):
    """J_k = tr(Ψ^{2k})."""
    return power_trace(t, t.Psi, 2 * k)


@claim("reduced-bracket-casimirs", paper=("REDUCED_BRACKET", "torus"), kind="pb",
       sizes=admissible(5, r_min=2, condition="r >= 2 (J_k exist for k <= [r/2])"),
       statement=r"X_{J_k}=(X\omega,P\omega),\ \omega=-4k\Psi^{2k-1}\in so(r);\quad \{J_k,\langle\Theta,a\rangle\}="
                 r"\{J_k,\Psi_\eta\}=\{\langle\Theta,a\rangle,\Psi_\eta\}=\{J_k,H_{neum,\kappa}\}=0,\quad J_k=\tr\Psi^{2k},\ "
                 r"k=1,2,3\ (\text{the paper: }k\le[r/2])")
def psi_powers_are_casimirs_of_the_reduced_bracket(s):
    """The Hamiltonian vector field of J_k = tr(Ψ^{2k}) (k = 1, 2, 3, as the trace functions of this section; the paper takes k ≤ [r/2], the independent ones: for r ≤ 7 they are among these, and for k > [r/2] J_k is a function of them, so the identities hold all the same; for r ≥ 8 the paper's J_4, …, J_{[r/2]} are not checked here) is the infinitesimal right action of ω = −4kΨ^{2k−1} ∈ so(r), tangent to the SO(r)-orbits, so J_k commutes with every SO(r)-invariant function (j_k is a Casimir of the reduced bracket {,}′), in particular with the components of Θ, and is an integral of the Neumann flows (No); and the functions (torus) commute with Ψ."""
    Theta_a = lambda t: t.killing(Theta(t), gl_generic(t, "a"))   # noqa: E731
    checks = {"{<Theta, a>, Psi_eta}": s.bracket(Theta_a, Psi_eta)}
    for k in POWERS:
        flow = s.dirac_flow(lambda t, k=k: J(t, k))
        omega = s.Psi
        for _ in range(2 * k - 2):
            omega = omega @ s.Psi
        omega = omega * (-4 * k)
        checks[f"X_J{k} - (X omega, P omega): X"] = flow.Xdot - s.X @ omega
        checks[f"X_J{k} - (X omega, P omega): P"] = flow.Pdot - s.P @ omega
        checks[f"{{J_{k}, <Theta, a>}}"] = s.bracket(lambda t, k=k: J(t, k), Theta_a)
        checks[f"{{J_{k}, Psi_eta}}"] = s.bracket(lambda t, k=k: J(t, k), Psi_eta)
        checks[f"{{J_{k}, H_neum,kappa}}"] = s.bracket(lambda t, k=k: J(t, k), H_neum_kappa)
    return checks


# -- the Clebsch–Perelomov–Bogoyavlenski system (CPB) --------------------------------------

@claim("cpb-hamiltonian", paper=("CPB", "neumann", "N0_XP2", "prep"), kind="id",
       statement=r"H_{neum_0}=H\circ\Theta,\ H=\tfrac12\langle h,h\rangle-\langle A,v\rangle;\quad "
                 r"\tfrac{d}{dt}\Theta=[v,A]+[h,v]\big|_{h=\Phi,\,v=XX^T}\ \text{along (N0\_XP2)}")
def neumann_normal_hamiltonian_is_pulled_back(s):
    """Remark after Theorem NEUMANN: H_neum₀ = H∘Θ with H = ½<h, h> − <A, v>, and along the Dirac flow of H_neum₀ the image Θ(X, P) = h + v moves by (CPB): ḣ = [v, A], v̇ = [h, v]."""
    flow = s.dirac_flow(H_neum0)
    h, v = s.Phi, s.X @ s.X.T
    return {
        "H_neum0 - H(Theta)": H_neum0(s) - H_cpb_value(s, Theta(s)),
        "dh/dt - [v, A]": s.d(lambda t: t.Phi, flow) - comm(v, s.A),
        "dv/dt - [h, v]": s.d(lambda t: t.X @ t.X.T, flow) - comm(h, v),
    }


@claim("cpb-flow", paper=("CPB", "central", "LAMBDA12"), kind="pb",
       statement=r"\dot x=\Lambda_1(\cdot,\nabla H)^\sharp\iff\dot h=[v,A],\ \dot v=[h,v];\quad "
                 r"\{\tr(\lambda h+v-\lambda^2A)^k,H\}_{\Lambda_1}=0,\ k\le3")
def cpb_is_the_hamiltonian_flow_of_H(s):
    """The Hamiltonian flow of H = ½<h, h> − <A, v> for Λ₁ on gl(n) is (CPB) ḣ = [v, A], v̇ = [h, v], and the functions (central) are its integrals (k = 1, 2, 3, at a generic point of gl(n))."""
    x, c = gl_generic(s, "x"), gl_generic(s, "c")
    h, v = skew(x), sym(x)
    T = lambda1()
    # <x', c> = Λ1(c, ∇H)|_x for a generic covector c: the flow, without a basis of gl(n)
    checks = {"Lambda1(c, grad H) - <[v, A] + [h, v], c>": T(s, x, c, H_CPB.grad(s, x))
              - s.killing(comm(v, s.A) + comm(h, v), c)}
    for k in POWERS:
        checks[f"{{tr L(lambda)^{k}, H}}_Lambda1"] = T.bracket(s, central(k, lambda t: t.lam), H_CPB, x)
    return checks


# -- A = 0: the integrals (FF) of the geodesic flows ---------------------------------------

@claim("ff-integrals", paper=("FF", "so(n)+so(r)", "EM"), kind="pb",
       statement=r"\{\tr(\lambda\Phi+XX^T)^k,\tr(\mu\Phi+XX^T)^m\}=\{\tr(\lambda\Phi+XX^T)^k,\Phi_\xi\}="
                 r"\{\tr(\lambda\Phi+XX^T)^k,\Psi_\eta\}=\{\tr(\lambda\Phi+XX^T)^k,H_\kappa\}=0,\ k,m\le3")
def ff_commute_and_are_integrals(s):
    """The functions (FF) tr(λ(PXᵀ − XPᵀ) + XXᵀ)^k, k = 1, 2, 3, commute for two values λ, μ, are SO(n)×SO(r)-invariant (they commute with Φ_ξ and Ψ_η) and are integrals of the geodesic flows of the Jensen metrics H_κ."""
    checks = {}
    for k in POWERS:
        f = lambda t, k=k: FF(t, t.lam, k)   # noqa: E731
        for m in POWERS:
            if m >= k:
                checks[f"{{FF_{k}(lambda), FF_{m}(mu)}}"] = s.bracket(f, lambda t, m=m: FF(t, mu(t), m))
        checks[f"{{FF_{k}, Phi_xi}}"] = s.bracket(f, Phi_xi)
        checks[f"{{FF_{k}, Psi_eta}}"] = s.bracket(f, Psi_eta)
        checks[f"{{FF_{k}, H_kappa}}"] = s.bracket(f, H_jensen)
    return checks


# -- the Manakov family on so(r) (BB), Theorem CIF, Corollaries nikinorov and COM -----------

def b_diagonal(t):
    """B = diag(B_1, ..., B_r) as printed after Theorem CIF, fresh parameters of the claim."""
    r = t.r
    b = [t.scalar(f"B_{i + 1}") for i in range(r)]
    return t.mat([[b[i] if i == j else t.q(0) for j in range(r)] for i in range(r)], ("r", "r"))


def b_symmetric(t):
    """A generic symmetric r x r matrix B.  The identities on T*V are checked for it: they are
    polynomial in B, so they hold for the diagonal B of the paper as a special case."""
    G = t.generic("B", "r", "r")
    return G + G.T


def manakov_so_r(t, xi, B=None):
    """𝔹(ξ) = Bξ + ξB, the Manakov operator on so(r)."""
    B = b_symmetric(t) if B is None else B
    return B @ xi + xi @ B


def bb(t, M, nu, k, B=None):
    """(BB): tr(M + νB)^k for M in so(r)."""
    B = b_symmetric(t) if B is None else B
    return power_trace(t, M + nu * B, k)


def half_form_generic(t, xi):
    """½<ξ, 𝔹ξ> = −¼tr(ξ𝔹(ξ)) for a generic operator 𝔹 on so(r), symmetric for <,>."""
    return -t.tr(xi @ t.sym_operator("BB")(xi)) / 4


def H_B_generic(t):
    """(HB): H_𝔹 = ½tr(PᵀP) − ¼tr(Ψ𝔹(Ψ)) = ½tr(PᵀP) + ½<Ψ, 𝔹Ψ> for a generic symmetric 𝔹 on so(r)."""
    return t.tr(t.P.T @ t.P) / 2 + half_form_generic(t, t.Psi)


def H_B_manakov(t):
    """(HB) with 𝔹(ξ) = Bξ + ξB: ½tr(PᵀP) − ¼tr(Ψ𝔹(Ψ))."""
    return t.tr(t.P.T @ t.P) / 2 - t.tr(t.Psi @ manakov_so_r(t, t.Psi)) / 4


def potential(t):
    """½tr(XᵀAX)."""
    return t.tr(t.X.T @ t.A @ t.X) / 2


@claim("bb-manakov-so-r", paper=("BB", "e-so(r)"), kind="pb",
       sizes=admissible(5, r_min=2, condition="r >= 2 (so(1) = 0)"),
       statement=r"\dot\xi=\{\xi,h_{\mathbb B}\}^-_{so(r)}=[\xi,\mathbb B\xi],\ \mathbb B\xi=B\xi+\xi B;\quad "
                 r"\{\tr(\xi+\mu B)^k,\tr(\xi+\nu B)^m\}^-=\{\tr(\xi+\mu B)^k,h_{\mathbb B}\}^-=0,\ k,m\le3")
def manakov_family_on_so_r(s):
    """(e-so(r)), (BB): for 𝔹(ξ) = Bξ + ξB, the Hamiltonian vector field of h_𝔹 = ½<ξ, 𝔹ξ> for the (−) Lie–Poisson bracket on so(r) is ξ̇ = [ξ, 𝔹ξ] (<ξ̇, θ> = {<·, θ>, h_𝔹}⁻ for a generic θ), and the functions tr(ξ + μB)^k commute with each other and with h_𝔹 (k, m = 1, 2, 3, at a generic ξ ∈ so(r); B generic symmetric, the diagonal B of the paper being a special case)."""
    T = lie_poisson(SO_R, -1)
    xi, theta = s.eta, s.theta
    h_B = quadratic(lambda t, x: manakov_so_r(t, x), "h_B")
    fam = lambda k, nu: trace_power(k, so_scale=lambda t: t.q(1), shift=lambda t: nu(t) * b_symmetric(t))  # noqa: E731
    checks = {"{<xi, theta>, h_B}^- - <[xi, B xi], theta>": T(s, xi, theta, h_B.grad(s, xi))
              - s.killing(comm(xi, manakov_so_r(s, xi)), theta)}
    for k in POWERS:
        for m in POWERS:
            if m >= k:
                checks[f"{{tr(xi+mu B)^{k}, tr(xi+nu B)^{m}}}^-"] = T.bracket(
                    s, fam(k, lambda t: t.lam), fam(m, mu), xi)
        checks[f"{{tr(xi+mu B)^{k}, h_B}}^-"] = T.bracket(s, fam(k, lambda t: t.lam), h_B, xi)
    return checks


@claim("cif-integrals", paper=("CIF", "HB", "BB", "FF"), kind="pb", exact_max_n=7,
       sizes=admissible(5, r_min=2, condition="r >= 2 (so(1) = 0)"),
       statement=r"\{\mathfrak B,\mathfrak B\}=\{\mathfrak B,\mathfrak F\}=\{\mathfrak B,\Phi_\xi\}=0,\ "
                 r"\mathfrak B=\{\tr(\Psi+\mu B)^k\};\quad \{\Phi_\xi,H_{\mathbb B}\}=\{\mathfrak F,H_{\mathbb B}\}=0;\ "
                 r"\{\mathfrak B,H_{\mathbb B}\}=0\ \text{for}\ \mathbb B\xi=B\xi+\xi B")
def cif_set_is_commutative_and_conserved(s):
    """Theorem CIF with the Manakov family (BB): 𝔅 = {tr(Ψ + μB)^k} and 𝔉 (FF) form a commutative set of SO(n)-invariant functions; for every symmetric 𝔹 on so(r) the geodesic flow of H_𝔹 (HB) has the integrals Φ and 𝔉, and for 𝔹(ξ) = Bξ + ξB also 𝔅 (k, m = 1, 2, 3; B generic symmetric, the diagonal B of the paper being a special case)."""
    checks = {}
    for k in POWERS:
        b_k = lambda t, k=k: bb(t, t.Psi, t.lam, k)   # noqa: E731
        for m in POWERS:
            if m >= k:
                checks[f"{{BB_{k}(lambda), BB_{m}(mu)}}"] = s.bracket(b_k, lambda t, m=m: bb(t, t.Psi, mu(t), m))
        checks[f"{{BB_{k}, FF_2}}"] = s.bracket(b_k, lambda t: FF(t, mu(t), 2))
        checks[f"{{BB_{k}, Phi_xi}}"] = s.bracket(b_k, Phi_xi)
        checks[f"{{BB_{k}, H_B (Manakov)}}"] = s.bracket(b_k, H_B_manakov)
    checks["{Phi_xi, H_B}"] = s.bracket(Phi_xi, H_B_generic)
    for k in POWERS:
        checks[f"{{FF_{k}, H_B}}"] = s.bracket(lambda t, k=k: FF(t, t.lam, k), H_B_generic)
    return checks


def block_parts(t, xi):
    """ξ₁ = DξD, ξ₂ = (I − D)ξ(I − D): the orthogonal projections of ξ ∈ so(r) to so(r₁) ⊕ 0 and 0 ⊕ so(r₂),
    D, I − D the projectors of ℝʳ = ℝ^{r₁} ⊕ ℝ^{r₂} (r₁ = ⌈r/2⌉ at fixed sizes, any two orthogonal blocks in
    the free algebra); ⟨ξᵢ, ξᵢ⟩ and tr ξᵢ^k are those of the r_i × r_i block (a block of size 1 is 0)."""
    return [twisted.block_projector(t, i) @ xi @ twisted.block_projector(t, i) for i in range(2)]


def K_of(t, xi):
    """(EM3): K(ξ) = κ₀/2<ξ, ξ> + Σ κᵢ/2<ξᵢ, ξᵢ>."""
    acc = t.scalar("kappa_0") * t.killing(xi, xi) / 2
    for i, xi_i in enumerate(block_parts(t, xi)):
        acc = acc + t.scalar(f"kappa_{i + 1}") * t.killing(xi_i, xi_i) / 2
    return acc


def H_K(t):
    """(EM2): H_K = ½<Φ, Φ> + K∘Ψ."""
    return t.killing(t.Phi, t.Phi) / 2 + K_of(t, t.Psi)


def chain_functions():
    """The chain functions of so(r₁) ⊕ so(r₂) ⊂ so(r): (name, f(t)) with f = tr Ψ^{2k}, tr Ψᵢ^{2k}, k = 1, 2
    (for r or r_i < 2k a function of the lower ones, or 0: its brackets vanish all the same)."""
    out = [(f"tr Psi^{2 * k}", lambda t, k=k: power_trace(t, t.Psi, 2 * k)) for k in (1, 2)]
    for i in range(2):
        for k in (1, 2):
            out.append((f"tr Psi_{i + 1}^{2 * k}",
                        lambda t, k=k, i=i: power_trace(t, block_parts(t, t.Psi)[i], 2 * k)))
    return out


@claim("nikinorov-integrals", paper=("nikinorov", "EM2", "EM3", "FF"), kind="pb",
       sizes=admissible(5, r_min=2, condition="r >= 2 (so(1) = 0)"),
       statement=r"H_K=\tfrac12\langle\Phi,\Phi\rangle+K\circ\Psi:\ \{\Phi_\xi,H_K\}=\{\mathfrak F,H_K\}=0,\ "
                 r"\{\tr\Psi^{2k},\cdot\}=\{\tr\Psi_i^{2k},\tr\Psi_j^{2m}\}=\{\tr\Psi_i^{2k},H_K\}=0")
def einstein_metric_flows_have_commuting_integrals(s):
    """Corollary nikinorov: the geodesic flow of H_K (EM2), (EM3) (here r = r₁ + r₂ with r₁ = ⌈r/2⌉ at fixed sizes; dimension-free, every orthogonal splitting of ℝʳ) has the integrals Φ and 𝔉 (FF), and the chain functions tr Ψ^{2k}, tr Ψᵢ^{2k} of so(r₁) ⊕ so(r₂) ⊂ so(r) commute with each other and with H_K (the bracket part of the statement)."""
    checks = {"{Phi_xi, H_K}": s.bracket(Phi_xi, H_K)}
    for k in POWERS:
        checks[f"{{FF_{k}, H_K}}"] = s.bracket(lambda t, k=k: FF(t, t.lam, k), H_K)
    chain = chain_functions()
    for i, (name, f) in enumerate(chain):
        checks[f"{{{name}, H_K}}"] = s.bracket(f, H_K)
        for name2, g in chain[i + 1:]:
            checks[f"{{{name}, {name2}}}"] = s.bracket(f, g)
    return checks


@claim("com-integrals", paper=("COM", "perelomov", "BB"), kind="pb", exact_max_n=7,
       sizes=admissible(5, r_min=2, condition="r >= 2 (so(1) = 0)"),
       statement=r"H_{neum,\mathbb B}=H_{\mathbb B}+\tfrac12\tr(X^TAX):\ \{\mathfrak F,H_{neum,\mathbb B}\}="
                 r"\{\mathfrak F,\mathfrak B\}=0,\ \mathfrak F\ \text{(perelomov)};\ \{\mathfrak B,H_{neum,\mathbb B}\}=0\ "
                 r"\text{for}\ \mathbb B\xi=B\xi+\xi B")
def neumann_with_b_metric_has_commuting_integrals(s):
    """Corollary COM: the integrals (perelomov) are conserved by the Neumann system H_neum,𝔹 for every symmetric 𝔹 on so(r) and commute with 𝔅 (BB); for 𝔹(ξ) = Bξ + ξB the functions of 𝔅 are conserved too (k = 1, 2, 3)."""
    H_gen = lambda t: H_B_generic(t) + potential(t)   # noqa: E731
    H_man = lambda t: H_B_manakov(t) + potential(t)   # noqa: E731
    checks = {}
    for k in POWERS:
        f = lambda t, k=k: perelomov(t, t.lam, k)   # noqa: E731
        checks[f"{{perelomov_{k}, H_neum,B}}"] = s.bracket(f, H_gen)
        checks[f"{{perelomov_{k}, BB_2}}"] = s.bracket(f, lambda t: bb(t, t.Psi, mu(t), 2))
    for k in POWERS:
        checks[f"{{BB_{k}, H_neum,B (Manakov)}}"] = s.bracket(lambda t, k=k: bb(t, t.Psi, t.lam, k), H_man)
    return checks


# -- singular A: the Noether integrals Φ_A ---------------------------------------------------

def A_with_eigenspace(t):
    """A = αD + (I − D)B(I − D), B a generic symmetric matrix: every symmetric A with the eigenvalue α on the range
    of the orthogonal projector D (AD = DA = αD)."""
    D, C = twisted.eigenspace_projector(t), t.In - twisted.eigenspace_projector(t)
    B = t.generic("B", "n", "n")
    return t.scalar("alpha") * D + C @ (B + B.T) @ C


def H_neum_eigenspace(t):
    """(neumann) with κ free and A = αD + (I − D)B(I − D)."""
    XtP = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(XtP @ XtP) + t.tr(t.X.T @ A_with_eigenspace(t) @ t.X) / 2


@claim("singular-a-noether", paper=("No", "momentum_map", "Phi"), kind="pb", exact_max_n=3,
       exact_max_r={4: 2, 5: 3, 6: 1, 7: 1}, exact_corank={4: 0, 5: 0, 6: 0, 7: 0},
       sizes=admissible(5, n_min=2, condition="n >= 2 (so(1) = 0)"),
       statement=r"a_1=\dots=a_{k_1},\dots:\quad \tfrac{d}{dt}\Phi_A=0,\ \Phi_A=\pr_{so(n)_A}(PX^T-XP^T),\quad "
                 r"\{\langle\Phi,\xi_A\rangle,H_{neum,\kappa}\}=0,\ \xi_A\in so(n)_A")
def isotropy_momentum_is_conserved(s):
    """For A with a repeated eigenvalue α, on the range of an orthogonal projector D (A = αD + (I − D)B(I − D), B generic symmetric: every symmetric A with that eigenspace), the block DΦD of Φ in so(range D) ⊂ so(n)_A is conserved by the Neumann flows (No) for every κ, and the linear functions <Φ, DξD> commute with H_neum,κ; summed over the eigenspaces of A, the momentum map Φ_A = pr_{so(n)_A}Φ of the isotropy group SO(n)_A is conserved and the <Φ, ξ_A>, ξ_A ∈ so(n)_A, are Noether integrals.  At fixed sizes D = diag(I_2, 0) (at n = 2, A = αI); dimension-free, every projector D (every eigenspace of every A) at once."""
    H = H_neum_eigenspace
    flow = s.dirac_flow(H)
    block = lambda t, M: twisted.eigenspace_projector(t) @ M @ twisted.eigenspace_projector(t)   # noqa: E731
    return {
        "A D - alpha D": A_with_eigenspace(s) @ twisted.eigenspace_projector(s)
        - s.scalar("alpha") * twisted.eigenspace_projector(s),
        "d(D Phi D)/dt": s.d(lambda t: block(t, t.Phi), flow),
        "{<Phi, D xi D>, H}": s.bracket(lambda t: t.killing(t.Phi, block(t, t.xi)), H),
    }


def W_point(t):
    """A generic constant n x r matrix W (parameters of the claim's own)."""
    return twisted.kernel_frame(t)


def H_neum_W(t):
    """(neumann), κ free, with A = αI + βWWᵀ: the eigenvalue α has the eigenspace ker Wᵀ of dimension n − r."""
    XtP = t.X.T @ t.P
    W = W_point(t)
    A = t.scalar("alpha") * t.In + t.scalar("beta") * (W @ W.T)
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(XtP @ XtP) + t.tr(t.X.T @ A @ t.X) / 2


@claim("singular-a-noether-covariant", paper=("No", "momentum_map", "Phi"), kind="pb", exact_max_n=4, exact_max_r={5: 3, 6: 2, 7: 2},
       sizes=admissible(5, where=lambda n, r: n - r >= 2, condition="n - r >= 2 (so(n - r) != 0)"),
       statement=r"A=\alpha\mathbf I+\beta WW^T:\ so(n)_A\supset so(\ker W^T),\quad "
                 r"\tfrac{d}{dt}\,Q\Phi Q=0\ \text{along (No)},\ Q=\det(W^TW)\mathbf I-W\,\mathrm{adj}(W^TW)W^T")
def isotropy_momentum_is_conserved_covariantly(s):
    """For A = αI + βWWᵀ (W a generic constant n x r matrix: the eigenvalue α has multiplicity n − r, on ker Wᵀ), the component QΦQ of Φ in so(ker Wᵀ) ⊂ so(n)_A (Q = det(WᵀW)·(the projector onto ker Wᵀ)) is conserved by the Neumann flows (No) for every κ: the Noether integrals of the SO(n − r) ⊂ SO(n)_A symmetry, stated covariantly so that the exact method may take X = X₀.  Dimension-free, Q is every symmetric matrix with QW = 0 (the projector onto ker Wᵀ among them)."""
    W = W_point(s)
    Q = twisted.kernel_annihilator(s)   # det(WᵀW)I − W adj(WᵀW)Wᵀ
    flow = s.dirac_flow(H_neum_W)
    dPhi = s.d(lambda t: t.Phi, flow)
    return {"Q W": Q @ W, "d(Q Phi Q)/dt": Q @ dPhi @ Q}


# -- completeness: the numbers of independent functions ---------------------------------------

def differentials(s, functions):
    """The rows df of scalar functions f of the scene, in the 2nr coordinates of X, P (the columns of
    s.jacobian): (∂f/∂X, ∂f/∂P) from s.gradient, one evaluation and one backward sweep per function
    (fewer passes than the 2nr directions of a Jacobian when the functions are few and short)."""
    n, r = s.n, s.r
    rows = []
    for f in functions:
        fX, fP = s.gradient(f)
        rows.append([fX[i, j] for i in range(n) for j in range(r)] + [fP[i, j] for i in range(n) for j in range(r)])
    return rows


def _differentials_on_TV(s, functions):
    """The matrix of the differentials of ``functions`` (scalar functions of the scene, each
    differentiated by its gradient) stacked on those of the constraints (cond_XP): its rank minus
    r(r + 1) is the number of functions independent on T*V."""
    return s.mat(differentials(s, functions) + s.jacobian(s.constraints.build))


def _dim_V(n, r):
    return r * n - r * (r + 1) // 2


def _two_l(n, r):
    """Lemma 2l."""
    return n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)


def _bb_functions(r):
    """(BB): tr(Ψ + μ_jB)^k, k = 1..r, at r + 1 values μ_j (all the coefficients in μ), as scalar
    functions of the scene (in the order μ_j, then k)."""
    def f(t, j, k):
        B = b_symmetric(t)
        return power_trace(t, t.Psi + t.scalar(f"mu{j}") * B, k)
    return [lambda t, j=j, k=k: f(t, j, k) for j in range(r + 1) for k in range(1, r + 1)]


def _perelomov_functions(count, n):
    """(perelomov): tr(λ_j(PXᵀ − XPᵀ) + XXᵀ − λ_j²A)^k, k = 1..n, at ``count`` values λ_j, as scalar
    functions of the scene (in the order λ_j, then k)."""
    def f(t, j, k):
        lam = t.scalar(f"lam{j}")
        return power_trace(t, lam * (t.P @ t.X.T - t.X @ t.P.T) + t.X @ t.X.T - lam * lam * t.A, k)
    return [lambda t, j=j, k=k: f(t, j, k) for j in range(count) for k in range(1, n + 1)]


def _FF_functions(count, n):
    """(FF): tr(λ_j(PXᵀ − XPᵀ) + XXᵀ)^k, k = 1..n, at ``count`` values λ_j, as scalar functions of the
    scene (in the order λ_j, then k)."""
    def f(t, j, k):
        lam = t.scalar(f"lam{j}")
        return power_trace(t, lam * (t.P @ t.X.T - t.X @ t.P.T) + t.X @ t.X.T, k)
    return [lambda t, j=j, k=k: f(t, j, k) for j in range(count) for k in range(1, n + 1)]


def tangent_coordinates(s, v):
    """A tangent vector {"X": δX, "P": δP} in the 2nr coordinates of X, P (the columns of :func:`differentials`)."""
    n, r = s.n, s.r
    return [v["X"][i, j] for i in range(n) for j in range(r)] + [v["P"][i, j] for i in range(n) for j in range(r)]


def vector_fields(s, fields):
    """The matrix whose columns are the tangent vectors ``fields``: a kernel certificate of a matrix of
    differentials in the coordinates of X, P (None, no certificate, when there are none: at (1, 1))."""
    if not fields:
        return None
    return s.mat([list(row) for row in zip(*(tangent_coordinates(s, v) for v in fields))])


def left_action_fields(s):
    """(ξX, ξP), ξ = E_i∧E_j: the infinitesimal SO(n)-action, tangent to T*V, annihilated by the differential
    of every SO(n)-invariant function."""
    return [{"X": xi @ s.X, "P": xi @ s.P} for xi in wedge_basis(s, s.n)]


def manakov_fields_needed(s, B):
    """Of the functions (BB) (``B``: tr(Ψ + μ_jB)^k in the order μ_j, then k), those whose Hamiltonian fields
    span the fields of all of them: tr(Ψ + μB)^k is a polynomial in μ whose nonconstant coefficients are those of
    μ^(k−2), μ^(k−4), … (a trace of a product with an odd number of factors Ψ vanishes), [k/2] of them, so
    [k/2] values of μ give its fields for every μ (k = 1 is the constant μ tr B)."""
    r = s.r
    return [B[j * r + k - 1] for k in range(2, r + 1) for j in range(k // 2)]


def cif_kernel(s, F, B):
    """Kernel vectors of the differentials of (FF), (BB) and (cond_XP) (Theorem CIF): the SO(n)-action, which
    fixes the SO(n)-invariant functions, and the Hamiltonian fields of the commuting functions (BB)
    (:func:`manakov_fields_needed`) and of (FF) at the first value of λ (k ≥ 2; tr(λΦ + XXᵀ) = r is constant).
    At n ≤ 7 they span the kernel, of dimension dim V + l (the SO(n)-orbits and the commutative set together)."""
    n = s.n
    return vector_fields(s, left_action_fields(s) + [s.dirac_flow(f) for f in manakov_fields_needed(s, B) + F[1:n]])


def com_kernel(s, F, B):
    """Kernel vectors of the differentials of (perelomov), (BB) and (cond_XP) (Corollary COM): the Hamiltonian
    fields of the commuting integrals (BB) (:func:`manakov_fields_needed`) and (perelomov), which span a
    Lagrangian kernel of dimension dim V as F + B is complete and commutative.  tr L(λ)^k, L(λ) = λΦ + XXᵀ − λ²A,
    is even in λ (L(λ)ᵀ = L(−λ)) with constant coefficients of λ⁰ and λ^2k, so k − 1 values of λ give its fields
    for every λ; the first min(k − 1, ⌈n/2⌉) values are taken (they suffice at n ≤ 7)."""
    n, r = s.n, s.r
    m = (n + 1) // 2
    chosen = manakov_fields_needed(s, B) + [F[j * n + k - 1] for k in range(2, n + 1) for j in range(min(k - 1, m))]
    return vector_fields(s, [s.dirac_flow(f) for f in chosen])


@claim("cif-completeness", paper=("CIF", "FF", "BB", "2l"), kind="dim", exact_max_n=3,
       exact_max_r={4: 4, 5: 4, 6: 3, 7: 2},
       equivariance="the rank of the differentials of SO(n)-invariant functions on T*V is invariant under O(n); the Jacobian only lists them in the coordinates of R^{2nr}",
       statement=r"\ddim(\mathfrak F+\mathfrak B)=\dim V_{n,r}-l,\quad \mathfrak F=\{\tr(\lambda\Phi+XX^T)^k\},\ "
                 r"\mathfrak B=\{\tr(\Psi+\mu B)^k\}")
def cif_set_is_complete(s):
    """Theorem CIF (ii): the functions (FF) and (BB) (k ≤ n and k ≤ r, at n + 1 and r + 1 values of λ and μ: all their coefficients) have dim V − l independent differentials on T*V, 2l the dimension of Lemma 2l, so the commutative set 𝔉 + 𝔅 is complete in the algebra of SO(n)-invariant functions."""
    n, r = s.n, s.r
    F, B = _FF_functions(n + 1, n), _bb_functions(r)
    return {"ddim(F + B)": Rank(_differentials_on_TV(s, F + B), _dim_V(n, r) - _two_l(n, r) // 2 + r * (r + 1),
                                generic=True, meaning="dim V - l + r(r+1): independent on T*V, plus the constraints",
                                kernel=cif_kernel(s, F, B))}


@claim("com-completeness", paper=("COM", "perelomov", "BB"), kind="dim", exact_max_n=4, exact_max_r={5: 1},
       equivariance="the rank of the differentials of the functions on T*V is invariant under (X, P, A) -> (gX, gP, gAg^T), which maps the set of functions to itself; the Jacobian only lists them in the coordinates of R^{2nr}",
       statement=r"\ddim(\mathfrak F+\mathfrak B)=\dim V_{n,r},\quad \mathfrak F=\{\tr(\lambda(PX^T-XP^T)+XX^T-\lambda^2A)^k\},\ "
                 r"\mathfrak B=\{\tr(\Psi+\mu B)^k\}")
def com_set_is_complete(s):
    """Corollary COM: the integrals (perelomov) and (BB) (k ≤ n and k ≤ r, at 2n + 1 and r + 1 values of λ and μ: all their coefficients) have dim V independent differentials on T*V, so with their commutativity they form a complete commutative set (Liouville integrability of H_neum,𝔹)."""
    n, r = s.n, s.r
    F, B = _perelomov_functions(2 * n + 1, n), _bb_functions(r)
    return {"ddim(F + B)": Rank(_differentials_on_TV(s, F + B), _dim_V(n, r) + r * (r + 1), generic=True,
                                meaning="dim V + r(r+1): independent on T*V, plus the constraints",
                                kernel=com_kernel(s, F, B))}
