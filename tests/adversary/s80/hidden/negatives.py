# ruff: noqa
"""s80 hidden round (h2): the false twins of claims.py, one change each (numpy in indep.py.in says where each is
false; `fails_at` states it)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, claim, comm, elementary
from stiefelsym.bases import matrix_of, matrix_units, so_basis

from _h80_helpers import (H_E, H_kappa_of, H_metric, H_neum_of, H_sub, dual_L, lam1, lam1_vec, lam2, lam2_vec)
from claims import _pow, dim_so, semidirect_tensor

ALL = admissible(n_max=5)
RN = admissible(n_max=5, r_is_n=True, condition="r = n")


@claim("n80-submersion-gradient-sign", paper=("submersion_metric", "dot_XP2"), kind="id", sizes=ALL,
       fails_at=lambda n, r: n >= 2, erratum="twin: -dH/dX = -AA(Phi) P (sign)",
       statement=r"-\partial H_{\mathbb A}/\partial X=-\mathbb A(\Phi)P")
def n_submersion_gradient_sign(s):
    """Twin of h80-submersion-gradient: the sign of −∂H/∂X changed."""
    AA = s.sym_operator("AA")
    HX, HP = s.gradient(lambda t: -t.tr(t.sym_operator("AA")(t.P @ t.X.T - t.X @ t.P.T) @ (t.P @ t.X.T - t.X @ t.P.T)) / 4)
    return {"dH/dP - AA(Phi) X": HP - AA(s.Phi) @ s.X, "-dH/dX + AA(Phi) P": -HX + AA(s.Phi) @ s.P}


@claim("n80-euclid-commutes-pap", paper=("so(n)+so(r)", "ET"), kind="pb", sizes=ALL,
       fails_at=lambda n, r: n >= 2 and r < n, erratum="twin: H_AA replaced by 1/2 tr(P^T A P)",
       statement=r"\{H_E,\tfrac12\tr(P^TAP)\}=0")
def n_euclid_commutes_pap(s):
    """Twin of h80-euclid-commutes-submersion: ½tr(PᵀAP) (not a function of Φ) in place of H_𝔸."""
    return {"{H_E, 1/2 tr P^T A P}": s.bracket(H_E, lambda t: t.tr(t.P.T @ t.A @ t.P) / 2)}


@claim("n80-lambda-kernel-sign", paper=("LEMA2", "LAMBDA", "L3", "L4"), kind="pb", sizes=ALL,
       fails_at=lambda n, r: n >= 2, erratum="twin: xi_k = +sum A^a h A^b",
       statement=r"\xi_k=+\sum_{a+b=k-1}A^ahA^b")
def n_lambda_kernel_sign(s):
    """Twin of h80-lambda-1m1-kernel-explicit: ξ_k with the opposite sign."""
    h, v, A = s.Phi, s.X @ s.X.T, s.A
    x = h + v
    z = s.fresh("n", "n")
    out = {}
    Ak = s.In
    xi = s.zeros(s.n, s.n, ("n", "n"))
    for k in range(4):
        if k > 0:
            xi = sum((_pow(A, a, s) @ h @ _pow(A, k - 1 - a, s) for a in range(k)), s.zeros(s.n, s.n, ("n", "n")))
            Ak = Ak @ A
        y = xi + Ak
        out[f"Lambda_(1,-1)(xi_{k} + A^{k}, z)"] = lam1(x, y, z) - lam2(x, A, y, z)
    return out


@claim("n80-a1-rank-lambda1", paper=("NEUMANN2", "LEMA2"), kind="dim", sizes=admissible(n_max=4),
       fails_at=lambda n, r: (n, r) not in ((1, 1), (2, 1)), erratum="twin: Lambda_1 alone (lambda_2 = 0)",
       statement=r"X^TP=0:\ \rank\Lambda_1(\Theta(X,P))=n^2-n")
def n_a1_rank_lambda1(s):
    """Twin of h80-a1-rank-psi-zero: the bracket Λ1 (λ₂ = 0) in place of Λ_{1,1} (its rank there is 2r(n − r))."""
    n = int(s.n)
    Pt = s.P - s.X @ (s.X.T @ s.P)
    x = (Pt @ s.X.T - s.X @ Pt.T) + s.X @ s.X.T
    M = matrix_of(s, lambda y: lam1_vec(x, y), matrix_units(s, "n", "n"))
    return {"rank Lambda_1 at Theta(Psi^-1(0))": Rank(M, n * n - n)}


@claim("n80-metric-psi-flow-sign", paper=("cond_XP2", "momentum_right_map"), kind="pb", realization="metric", sizes=ALL,
       fails_at=lambda n, r: r >= 2, erratum="twin: X-flow of Psi_eta = -X eta",
       statement=r"X_{\Psi_\eta}=(-X\eta,P\eta)")
def n_metric_psi_flow_sign(s):
    """Twin of h80-metric-psi-momentum-map: the X-component with the opposite sign."""
    eta, zeta = s.eta, s.generic("Z", "r", "r", "skew")
    psi_eta = lambda t: t.killing(t.X.T @ t.P - t.P.T @ t.X, t.eta)
    psi_zeta = lambda t: t.killing(t.X.T @ t.P - t.P.T @ t.X, t.generic("Z", "r", "r", "skew"))
    flow = s.dirac_flow(psi_eta)
    return {"X-flow of Psi_eta + X eta": flow.Xdot + s.X @ eta,
            "P-flow of Psi_eta - P eta": flow.Pdot - s.P @ eta,
            "{Psi_eta, Psi_zeta}_A + <Psi, [eta, zeta]>": s.bracket(psi_eta, psi_zeta) + s.killing(s.Psi, comm(eta, zeta))}


@claim("n80-dual-lax-generic-submersion-r-n", paper=("DUAL", "LA3", "submersion_metric"), kind="pb", sizes=RN,
       fails_at=lambda n, r: n >= 3, erratum="twin: the generic submersion flow H_AA in place of H_0",
       statement=r"r=n:\ \tfrac{d}{dt}e_k(\mathcal L^*)=\tfrac{d}{dt}\tr\mathcal L^k=0\ \text{along }H_{\mathbb A},\ H_E")
def n_dual_lax_generic_submersion_r_n(s):
    """Twin of h80-dual-lax-bi-invariant-r-n: the flow of a generic submersion Hamiltonian H_𝔸 in place of H_0."""
    out = {}
    for name, H in (("H_AA", H_sub), ("H_E", H_E)):
        flow = s.dirac_flow(H)
        for k in (2, 4):
            out[f"d e_{k}(L*) along {name}"] = s.d(lambda t, k=k: elementary(t, dual_L(t, t.lam), k)[k], flow)
        for k in (2, 3):
            def big(t, k=k):
                L = t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
                M = L
                for _ in range(k - 1):
                    M = M @ L
                return t.tr(M)
            out[f"d tr L^{k} along {name}"] = s.d(big, flow)
    return out


@claim("n80-theta1-orbit-index", paper=("LAMBDA12", "momentum_map"), kind="dim", sizes=admissible(n_max=5),
       fails_at=lambda n, r: True, erratum="twin: 2nr - r(r-1)",
       statement=r"\rank\pi(\Phi,X)=2nr-r(r-1)")
def n_theta1_orbit_index(s):
    """Twin of h80-theta1-coadjoint-orbit: r(r − 1) in place of r(r + 1)."""
    n, r = int(s.n), int(s.r)
    return {"rank at Theta_1(X, P)": Rank(semidirect_tensor(s, s.Phi, s.X), 2 * n * r - r * (r - 1))}


@claim("n80-so-n-orbit-x-isotropy", paper=("ddim",), kind="dim", sizes=admissible(n_max=5, n_min=2),
       fails_at=lambda n, r: n - r >= 2, erratum="twin: the isotropy so(n - r) of X alone",
       statement=r"\rank\{\xi\mapsto(\xi X,\xi P)\}=\dim so(n)-\dim so(n-r)")
def n_so_n_orbit_x_isotropy(s):
    """Twin of h80-so-n-orbit-dimension: dim so(n − r) (the isotropy of X alone) subtracted."""
    n, r = int(s.n), int(s.r)
    so = so_basis(s, "n")
    cols = []
    for xi in so:
        a, b = xi @ s.X, xi @ s.P
        cols.append([a[i, j] for i in range(n) for j in range(r)] + [b[i, j] for i in range(n) for j in range(r)])
    M = s.mat([[cols[j][i] for j in range(len(so))] for i in range(2 * n * r)], ("?", "?"))
    return {"rank": Rank(M, dim_so(n) - dim_so(n - r))}
