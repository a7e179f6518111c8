# ruff: noqa
"""s78 hidden round: one FALSE twin of each statement of claims.py (one change each), with fails_at where numpy
(indep.py.in) finds the twin false."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, admissible, block, claim, comm, det
from stiefelsym.bases import so_basis

from _h78_helpers import (H_neum, H_neum_k, L_dual, dim_V, dim_so, ddim_printed, eta_hat, fibre_lift, killing,
                          normal_gram, phi_of, phi0, thimm_gradient, two_l_printed)

SMALL = admissible(n_max=4)
N_GE_2 = admissible(n_max=5, n_min=2, r_max=1, condition="n >= 2 (so(1) = 0); the statement does not involve r")
CORANK_1 = admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1")
N_IS_2R = admissible(n_max=4, n_min=2, where=lambda n, r: n == 2 * r, condition="n = 2r")
TWO_R_LE_N = admissible(n_max=6, n_min=2, where=lambda n, r: 2 * r <= n, condition="n >= 2r")
ERR = "false twin (s78 hidden round)"


@claim("n78-thimm-plus-sign", paper=("iso",), kind="pb", sizes=SMALL,
       fails_at=lambda n, r: r >= 2 and n >= 3, erratum=ERR)
def thimm_plus_sign(s):
    """Twin of h78-thimm-invariant-bracket: the (+) Lie–Poisson sign {F, G} = +⟨Φ, [∇f̃, ∇g̃]⟩."""
    S = s.generic("S", "r", "r", "sym")
    T = s.generic("T", "r", "r", "sym")
    C = s.generic("C", "r", "r")
    F = lambda t: t.tr(S @ t.P.T @ t.P)
    G = lambda t: t.tr(C @ t.X.T @ t.P)
    H = lambda t: t.tr(T @ t.P.T @ t.P @ t.P.T @ t.P)
    gF, gG, gH = thimm_gradient(s, F), thimm_gradient(s, G), thimm_gradient(s, H)
    return {"{F,G} - <Phi,[dF,dG]>": s.bracket(F, G) - killing(s, s.Phi, comm(gF, gG)),
            "{F,H} - <Phi,[dF,dH]>": s.bracket(F, H) - killing(s, s.Phi, comm(gF, gH))}


@claim("n78-edelman-plus-quarter", paper=("Phi_0",), kind="id", sizes=SMALL, fails_at=lambda n, r: r >= 2,
       erratum=ERR)
def edelman_plus_quarter(s):
    """Twin of h78-edelman-lagrangian: L₀ = ½tr(ẊᵀẊ) + ¼tr(ẊᵀXXᵀẊ)."""
    V, X = s.P, s.X
    L0 = killing(s, phi0(s, V), phi0(s, V)) / 2
    P = V - X @ X.T @ V / 2
    return {"L0 - Edelman form": L0 - (s.tr(V.T @ V) / 2 + s.tr(V.T @ X @ X.T @ V) / 4),
            "X^T P + P^T X": X.T @ P + P.T @ X}


@claim("n78-gras-wedge-unprojected", paper=("neum-gras",), kind="id", sizes=CORANK_1, fails_at=lambda n, r: r >= 2,
       erratum=ERR)
def gras_wedge_unprojected(s):
    """Twin of h78-gras-wedge-corank-one: PηPᵀ = 0 with P itself (the projection I − XXᵀ dropped)."""
    Pt = (s.In - s.X @ s.X.T) @ s.P
    return {"P eta P^T": s.P @ s.eta @ s.P.T, "X^T Pt": s.X.T @ Pt}


@claim("n78-lax-left-action", paper=("prep",), kind="id", sizes=SMALL,
       fails_at=lambda n, r: n >= 3 or (n == 2 and r == 1), erratum=ERR)
def lax_left_action(s):
    """Twin of h78-lax-does-not-fix-flow: the LEFT vector field (ξX, ξP) added instead of (Xη, Pη)."""
    fl = s.dirac_flow(H_neum_k)
    V = {"X": fl.Xdot + s.xi @ s.X, "P": fl.Pdot + s.xi @ s.P}
    pi = s.X @ s.X.T
    return {"dPhi - [XX^T, A]": s.d(lambda t: t.Phi, V) - comm(pi, s.A),
            "d(XX^T) - [Phi, XX^T]": s.d(lambda t: t.X @ t.X.T, V) - comm(s.Phi, pi),
            "d(X^T X)": s.d(lambda t: t.X.T @ t.X, V),
            "d(X^T P + P^T X)": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, V)}


@claim("n78-gl-killing-sym-positive", paper=("symmetric-pair",), kind="id", sizes=SMALL,
       fails_at=lambda n, r: True, erratum=ERR)
def gl_killing_sym_positive(s):
    """Twin of h78-gl-killing-signature: ⟨S, S⟩ = +½tr(SᵀS) on Sym(n)."""
    K = s.generic("K", "n", "n", "skew")
    S = s.generic("S", "n", "n", "sym")
    v = s.X @ s.X.T
    return {"<K,K> - |K|^2/2": killing(s, K, K) - s.tr(K.T @ K) / 2,
            "<S,S> - |S|^2/2": killing(s, S, S) - s.tr(S.T @ S) / 2,
            "<K,S>": killing(s, K, S),
            "<Phi, XX^T>": killing(s, s.Phi, v),
            "<XX^T, XX^T> + r/2": killing(s, v, v) + s.tr(s.Ir) / 2}


@claim("n78-delta0-n-minus-r", paper=("bols-jov",), kind="dim", sizes=TWO_R_LE_N,
       fails_at=lambda n, r: n != 2 * r, erratum=ERR)
def delta0_n_minus_r(s):
    """Twin of h78-delta0-grassmannian: δ₀ = n − r."""
    n, r = int(s.n), int(s.r)
    d0 = 2 * dim_V(n, r) - ddim_printed(n, r) - two_l_printed(n, r)
    return {"delta_0 = n - r": Count(d0, n - r), "r = rank G(n,r)": Count(r, min(r, n - r))}


@claim("n78-n2r-det-along-neumann", paper=("Chasles-Manakov", "N0_XP2"), kind="pb", sizes=N_IS_2R,
       fails_at=lambda n, r: True, erratum=ERR)
def n2r_det_along_neumann(s):
    """Twin of h78-n2r-det-phi: det(Pᵀ(I − XXᵀ)P) conserved along the Neumann flow (N0_XP2) instead of (dot_XP3*)."""
    G = normal_gram(s)
    fl = s.dirac_flow(H_neum(s.q(0)))
    return {"det Phi - det G": det(s, s.Phi) - det(s, G),
            "d det G / dt": s.d(lambda t: det(t, t.P.T @ (t.In - t.X @ t.X.T) @ t.P), fl)}


@claim("n78-dual-lax-covariance-order", paper=("2r-integrals",), kind="id", sizes=SMALL,
       fails_at=lambda n, r: r >= 2, erratum=ERR)
def dual_lax_covariance_order(s):
    """Twin of h78-dual-lax-covariance: d/ds 𝓛*(Xe^{sη}, Pe^{sη}) = [diag(η, η), 𝓛*] (order reversed)."""
    lam = s.lam
    D = s.d(lambda t: L_dual(t, t.X, t.P, lam), {"X": s.X @ s.eta, "P": s.P @ s.eta})
    L = L_dual(s, s.X, s.P, lam)
    return {"dL* - [eta_hat, L*]": D - comm(eta_hat(s, s.eta), L)}


@claim("n78-so-n-killing-form-n", paper=("normal_metric",), kind="id", sizes=N_GE_2,
       fails_at=lambda n, r: True, erratum=ERR)
def so_n_killing_form_n(s):
    """Twin of h78-so-n-killing-form: tr(ad_ξ ad_ζ) = n tr(ξζ) (the constant of gl(n)/su(n) style, not n − 2)."""
    xi, zeta = s.xi, s.zeta
    basis = so_basis(s, "n")
    B = killing(s, basis[0], comm(xi, comm(zeta, basis[0])))
    for E in basis[1:]:
        B = B + killing(s, E, comm(xi, comm(zeta, E)))
    return {"B(xi,zeta) - n tr(xi zeta)": B - int(s.n) * s.tr(xi @ zeta)}


@claim("n78-iso-projection-identity", paper=("iso",), kind="id", sizes=SMALL,
       fails_at=lambda n, r: n - r >= 2, erratum=ERR)
def iso_projection_identity(s):
    """Twin of h78-iso-projection: Φ(X, L(ξ)) = ξ on all of so(n) (the projection onto 𝔳 dropped)."""
    L = fibre_lift(s, s.xi)
    return {"X^T L + L^T X": s.X.T @ L + L.T @ s.X, "Phi(X, L(xi)) - xi": phi_of(s, s.X, L) - s.xi}


@claim("n78-gras-reduced-dimension-once", paper=("grassmannian",), kind="dim", sizes=admissible(n_max=6),
       fails_at=lambda n, r: r >= 2, erratum=ERR)
def gras_reduced_dimension_once(s):
    """Twin of h78-gras-reduced-dimension: dim so(r) subtracted once (2 dim V − dim so(r) = 2r(n − r))."""
    n, r = int(s.n), int(s.r)
    red = 2 * dim_V(n, r) - dim_so(r)
    return {"dim = 2r(n-r)": Count(red, 2 * r * (n - r)),
            "= 2 dim G": Count(red, 2 * (dim_so(n) - dim_so(r) - dim_so(n - r)))}


@claim("n78-dual-lax-a-sign", paper=("LA4",), kind="id", sizes=SMALL, fails_at=lambda n, r: r >= 2, erratum=ERR)
def dual_lax_a_sign(s):
    """Twin of h78-dual-lax-conjugation-sp: κ = 0 block −PᵀX replaced by +PᵀX."""
    I, Z = s.Ir, s.zeros(s.r, s.r, ("r", "r"))
    Lam = s.X.T @ s.A @ s.X - s.P.T @ s.P
    K = s.X.T @ s.P
    J = block([[Z, I], [-I, Z]])
    A0 = block([[K, I], [Lam - s.lam * I, K.T]])
    AE = block([[Z, I], [Lam - s.lam * I, Z]])
    return {"J A0 sym": J @ A0 - (J @ A0).T, "J AE sym": J @ AE - (J @ AE).T}


from stiefelsym import Rank
from stiefelsym.systems import complex_point, ctranspose, re_trace, real_complex_point, realify_real


def _psi0(t, z):
    return ctranspose(t, z["Z"]) @ t.conj(z["Zdot"]) - ctranspose(t, z["Zdot"]) @ t.conj(z["Z"])


def _u1_sum(t, z):
    return z["Zdot"] @ ctranspose(t, t.conj(z["Z"])) - z["Z"] @ ctranspose(t, t.conj(z["Zdot"]))


@claim("n78-complex-u1-center-sign", paper=("u(1)",), kind="id", sizes=SMALL, fails_at=lambda n, r: True,
       erratum=ERR)
def complex_u1_center_sign(s):
    """Twin of h78-complex-u1-center: Σⱼ ψⱼ = +tr ψ₀."""
    z = complex_point(s)
    In_i = s.realify(s.In - s.In, s.In)
    Ir_i = s.realify(s.Ir - s.Ir, s.Ir)
    M, p0 = _u1_sum(s, z), _psi0(s, z)
    zr = real_complex_point(s)
    return {"Re(tr M - tr psi_0)": re_trace(s, M) - re_trace(s, p0),
            "Im(tr M - tr psi_0)": re_trace(s, In_i @ M) - re_trace(s, Ir_i @ p0),
            "psi_0 at real data - Psi": _psi0(s, zr) - realify_real(s, s.Psi)}


@claim("n78-psi-generic-rank-r", paper=("NEUMANN",), kind="dim", sizes=admissible(n_max=5),
       fails_at=lambda n, r: r % 2 == 1, erratum=ERR)
def psi_generic_rank_r(s):
    """Twin of h78-psi-generic-rank: rank Ψ = r (false for odd r: Ψ ∈ so(r))."""
    return {"rank Psi": Rank(s.Psi, int(s.r))}
