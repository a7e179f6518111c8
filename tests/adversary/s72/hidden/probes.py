# ruff: noqa
"""s72 probes of the engine (not statements of the paper): the hypotheses r = 1 / r = n of the dimension-free
method (r_in, r_is_n), and a false twin of (prep) off by 10⁻³⁰ (float and ball)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, comm, elementary

from _h72_helpers import H_neum_kappa, L_neum, Psi_of


@claim("p72-psi2-gram-r1-rn", kind="pb", sizes=admissible(n_max=4, r_in=(1, "n")))
def psi2_gram_r1_rn(s):
    """True at r = 1 (Ψ = 0) and at r = n (PᵀP = −(XᵀP)² commutes with Ψ = 2XᵀP); false for 1 < r < n."""
    N = s.generic("N", "r", "r", "sym")
    f = lambda t: t.tr(Psi_of(t.X, t.P) @ Psi_of(t.X, t.P))
    return {"{tr Psi^2, tr N P^TP}": s.bracket(f, lambda t: t.tr(N @ t.P.T @ t.P))}


@claim("p72-lax-plus-a-r-n", kind="lax", sizes=admissible(n_max=4, r_is_n=True))
def lax_plus_a_rn(s):
    """True at r = n (Φ is conserved and XXᵀ = I): e_k of λΦ + XXᵀ + λ²A conserved along H_neum,κ."""
    flow = s.dirac_flow(H_neum_kappa)
    return {f"d e_{k}/dt": s.d(lambda t, k=k: elementary(t, L_neum(t, t.lam, +1), 3)[k], flow) for k in (2, 3)}


@claim("p72-xptp-r1-rn", kind="id", sizes=admissible(n_max=4, r_in=(1, "n")), fails_at=lambda n, r: r == 1 and n >= 2,
       erratum="probe: XPᵀP = PPᵀX holds at r = n, not at r = 1")
def xptp(s):
    """XPᵀP − PPᵀX = 0: false at r = 1 (= |p|²e), true at r = n (both −XW², P = XW)."""
    return {"XP^TP - PP^TX": s.X @ s.P.T @ s.P - s.P @ s.P.T @ s.X}


@claim("p72-prep-tiny", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r < n,
       erratum="probe: (prep) with a factor 1 + 10^-30")
def prep_tiny(s):
    """(prep) off by 10⁻³⁰: dΦ/dt = (1 + 10⁻³⁰)[XXᵀ, A] along H_neum,κ (false wherever [XXᵀ, A] ≠ 0, i.e. r < n)."""
    flow = s.dirac_flow(H_neum_kappa)
    c = s.q(1) + s.q(1, 10 ** 30)
    return {"dPhi/dt - c[XX^T, A]": s.d(lambda t: t.P @ t.X.T - t.X @ t.P.T, flow) - comm(s.X @ s.X.T, s.A) * c}


@claim("p72-r-n-geodesic-r-is-n", kind="id", sizes=admissible(n_max=4, r_is_n=True))
def r_n_geodesic_r_is_n(s):
    """h72-neumann-r-n-geodesic with r_is_n=True (XXᵀ = I a hypothesis of the dimension-free method)."""
    flow = s.dirac_flow(H_neum_kappa)
    c = (s.kappa + 1) * 2
    return {"Xdot": flow["X"] - s.P * c, "Pdot": flow["P"] - s.P @ s.X.T @ s.P * c}


@claim("p72-r-n-geodesic-r-is-n-factor", kind="id", sizes=admissible(n_max=4, r_is_n=True),
       fails_at=lambda n, r: n >= 2, erratum="probe: (1 + κ) in place of 2(1 + κ)")
def r_n_geodesic_r_is_n_factor(s):
    """Twin with (1 + κ), r_is_n=True."""
    flow = s.dirac_flow(H_neum_kappa)
    c = s.kappa + 1
    return {"Xdot": flow["X"] - s.P * c, "Pdot": flow["P"] - s.P @ s.X.T @ s.P * c}
