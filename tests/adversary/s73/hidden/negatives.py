# ruff: noqa
"""s73 hidden round: false twins of claims.py, one change each, with `fails_at` where numpy (indep.py) finds the
twin false.  Helpers in _h73_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, Rank, admissible, claim, comm, det, twisted
from stiefelsym.systems import complex_point, coupled_point, derivative, realify_real, stiefel_pairs_flow

from _h73_helpers import (H_coupled, H_quartic, L_big, L_dual, Lambda_complex, Phi_of, Psi_of, cayley, cstar,
                          sphere_flow, tr_pow, uhlenbeck_F, unitary_r, wedge2)

R_IS_1 = admissible(n_max=4, n_min=2, r_max=1, condition="r = 1, n >= 2 (distinct a_i)")
R_IS_2 = admissible(n_max=4, r_min=2, r_max=2, condition="r = 2")
ALWAYS = lambda n, r: True


@claim("n73-uhlenbeck-sums-minus", paper=("Mum_geod",), kind="id", sizes=R_IS_1, fails_at=ALWAYS,
       erratum="twin: Σ a_iF_i = (Ae, e) − (p, p) (sign of (p, p))")
def uhlenbeck_sums_minus(s):
    """False twin of h73-uhlenbeck-sums: Σ a_iF_i = (Ae, e) − (p, p)."""
    F, a, e, p, A = uhlenbeck_F(s), s.a, s.X, s.P, s.A
    Sa = a[0] * F[0]
    for i in range(1, int(s.n)):
        Sa = Sa + a[i] * F[i]
    return {"sum a_i F_i - (Ae,e) + (p,p)": Sa - s.tr(e.T @ A @ e) + s.tr(p.T @ p)}


def H_uhlenbeck_full(t):
    F, a = uhlenbeck_F(t), t.a
    acc = a[0] * F[0]
    for i in range(1, int(t.n)):
        acc = acc + a[i] * F[i]
    return acc


@claim("n73-uhlenbeck-flow-factor", paper=("Mum_geod", "sphere_neum"), kind="id", sizes=R_IS_1, fails_at=ALWAYS,
       erratum="twin: α_i = a_i (the factor ½ dropped)")
def uhlenbeck_flow_factor(s):
    """False twin of h73-uhlenbeck-neumann-flow: the flow of Σ a_iF_i is (sphere_neum)'s flow."""
    fl = s.dirac_flow(H_uhlenbeck_full)
    ref = sphere_flow(s)
    return {"edot": fl["X"] - ref["X"], "pdot": fl["P"] - ref["P"]}


@claim("n73-quartic-lambda-sign", paper=("quartic",), kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: n >= 2, erratum="twin: Λ = 2XᵀA²X − 4(XᵀAX)² + PᵀP")
def quartic_lambda_sign(s):
    """False twin of h73-quartic-flow: + PᵀP in Λ."""
    X, P, A = s.X, s.P, s.A
    M = X.T @ A @ X
    fl = s.dirac_flow(H_quartic)
    Lam = (X.T @ A @ A @ X) * 2 - (M @ M) * 4 + P.T @ P
    return {"Pdot": fl["P"] - (-(A @ A @ X) * 2 + (A @ X @ M) * 4 + X @ Lam)}


@claim("n73-wedge-reflection", paper=("grassmannian",), kind="id", sizes=R_IS_2, fails_at=ALWAYS,
       erratum="twin: h = diag(1, −1) ∈ O(2) \\ SO(2)")
def wedge_reflection(s):
    """False twin of h73-so2-wedge-invariant: e_1∧e_2 is unchanged by the reflection h = diag(1, −1)."""
    h = s.mat([[1, 0], [0, -1]], ("r", "r"))
    return {"e1^e2": wedge2(s, s.X @ h) - wedge2(s, s.X)}


@claim("n73-psi-zero-rank-high", paper=("grassmannian",), kind="dim", sizes=admissible(n_max=4), fails_at=ALWAYS,
       erratum="twin: rank r(r + 1) + r²")
def psi_zero_rank_high(s):
    """False twin of h73-psi-zero-regular: rank r(r + 1) + r²."""
    r = int(s.r)
    J = s.mat(s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P]))
    return {"rank": Rank(J, r * (r + 1) + r * r)}


@claim("n73-mag0-rank-plus-one", paper=("mag0",), kind="dim",
       sizes=admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1"),
       fails_at=ALWAYS, erratum="twin: one more")
def mag0_rank_plus_one(s):
    """False twin of h73-mag0-rank: rank n(n−1) + (n−1)(n+2)/2 + 1."""
    n, r = int(s.n), int(s.r)
    rows = s.jacobian(s.constraints.build) + s.jacobian(lambda t: [Phi_of(t.X, t.P), t.X @ t.X.T])
    return {"rank": Rank(s.mat(rows), r * (r + 1) + n * (n - 1) // 2 + n)}


@claim("n73-mag0-count-n", paper=("mag0",), kind="dim",
       sizes=admissible(n_max=6, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1"),
       fails_at=ALWAYS, erratum="twin: dim S^{n−1} counted as n")
def mag0_count_n(s):
    """False twin of h73-mag0-count: dim so(n) + n."""
    n, r = int(s.n), int(s.r)
    dimV = n * r - r * (r + 1) // 2
    return {"dim": Count(2 * dimV - r * (r - 1) // 2, n * (n - 1) // 2 + n)}


@claim("n73-dual-big-plus-a", paper=("DUAL", "perelomov"), kind="pb", sizes=admissible(n_max=4),
       fails_at=lambda n, r: n >= 2 and r < n, erratum="twin: 𝓛(μ) = μΦ + XXᵀ + μ²A")
def dual_big_plus_a(s):
    """False twin of h73-dual-big-commute: + μ²A in 𝓛(μ) (at r = n it holds after all: XXᵀ = I and
    tr 𝓛₊(μ)² = μ²tr Φ² + const, tr Φ² a function of Ψ there)."""
    mu = s.scalar("mu")
    Lp = lambda t: Phi_of(t.X, t.P) * mu + t.X @ t.X.T + t.A * (mu * mu)
    return {"{tr L*^2, tr L+^2}": s.bracket(lambda t: tr_pow(t, L_dual(t, t.lam), 2),
                                            lambda t: tr_pow(t, Lp(t), 2))}


@claim("n73-invariants-trace-commutes-not", paper=("SO(n)-inv",), kind="not", expect="nonzero",
       sizes=admissible(n_max=4, r_min=2), fails_at=ALWAYS,
       erratum="twin: tr PᵀP is right SO(r)-invariant, so {tr PᵀP, Ψ_η} = 0")
def invariants_trace_not(s):
    """False twin (`not`) of h73-invariants-noncommutative: {tr PᵀP, Ψ_η} ≠ 0."""
    eta = s.eta
    return {"{tr P^TP, Psi_eta}": s.bracket(lambda t: t.tr(t.P.T @ t.P), lambda t: t.tr(eta @ Psi_of(t.X, t.P)))}


@claim("n73-dual-det-no-a", paper=("2r-integrals",), kind="id",
       sizes=admissible(n_max=4, r_is_n=True, condition="r = n"), fails_at=ALWAYS,
       erratum="twin: det 𝓛*(λ) = 1 (a(λ) dropped)")
def dual_det_no_a(s):
    """False twin of h73-dual-det-r-n: det 𝓛*(λ) = 1."""
    return {"det L* - 1": det(s, L_dual(s, s.lam)) - 1}


@claim("n73-complex-lambda-order", paper=("W-L",), kind="id", sizes=admissible(n_max=3, r_max=2),
       fails_at=lambda n, r: r >= 2, erratum="twin: Λ(ZU) = UΛU*")
def complex_lambda_order(s):
    """False twin of h73-complex-u-r-symmetry: Λ(ZU, ŻU) = UΛU*."""
    z = complex_point(s)
    Z, Zd = z["Z"], z["Zdot"]
    U = unitary_r(s, s.eta, s.generic("S", "r", "r", "sym"))
    return {"Lambda(ZU) - U Lambda U*": Lambda_complex(s, Z @ U, Zd @ U) - U @ Lambda_complex(s, Z, Zd) @ cstar(U)}


@claim("n73-coupled-prep-projectors", paper=("C-neumann",), kind="pb", sizes=admissible(n_max=3),
       fails_at=lambda n, r: n >= 2, erratum="twin: [XXᵀ + YYᵀ, A]")
def coupled_prep_projectors(s):
    """False twin of h73-coupled-prep: d/dt(Φ(X,P) + Φ(Y,Q)) = [XXᵀ + YYᵀ, A]."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_coupled, z, [("X", "P"), ("Y", "Q")])
    X, Y, A = z["X"], z["Y"], s.A
    return {"d(Phi_X + Phi_Y)/dt - [XX^T + YY^T, A]":
                derivative(s, lambda t, w: Phi_of(w["X"], w["P"]) + Phi_of(w["Y"], w["Q"]), z, fl)
                - comm(X @ X.T + Y @ Y.T, A)}


def H_neum_kappa(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("n73-twisted-p1p2", paper=("twisted", "mag-euk"), kind="pb", sizes=R_IS_2, fails_at=lambda n, r: n >= 3,
       erratum="twin: (p_1, p_2) in place of Ψ_12")
def twisted_p1p2(s):
    """False twin of h73-twisted-psi12-any-kappa: (p_1, p_2) is conserved by the twisted flow of H_neum,κ.
    (My first twin, (e_1, p_2) alone, is Ψ_12/2 on T*V: the engine rightly found it conserved; at n = r = 2,
    PᵀP = w²I and (p_1, p_2) = 0.)"""
    fk = twisted.flow(s, H_neum_kappa)
    return {"d(p1,p2)/dt": s.d(lambda t: (t.P.T @ t.P)[0, 1], fk)}


@claim("n73-invariants-noncommutative-2-2", paper=("SO(n)-inv", "LEMA"), kind="not", expect="nonzero",
       sizes=admissible(n_min=2, stated_n_max=2, r_min=2, condition="n = r = 2"), fails_at=ALWAYS,
       erratum="twin: h73-invariants-noncommutative stated at n = r = 2, where PᵀP = w²I is SO(2)-invariant")
def invariants_noncommutative_2_2(s):
    """False twin (`not`) of h73-invariants-noncommutative at the excluded size (2, 2): {tr(S PᵀP), Ψ_η} ≠ 0."""
    S = s.generic("S", "r", "r", "sym")
    eta = s.eta
    return {"{tr(S P^TP), Psi_eta}": s.bracket(lambda t: t.tr(S @ t.P.T @ t.P),
                                               lambda t: t.tr(eta @ Psi_of(t.X, t.P)))}
