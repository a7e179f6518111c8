# ruff: noqa
"""s79 hidden round: the false twins of claims.py, one change each; numpy (indep.py.in) says where each twin is
false.  Run with  stiefelsym verify --claims tests/adversary/s79/hidden/negatives.py --method M --jobs 1 --timeout 120"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, claim, comm, elementary
from stiefelsym import twisted
from stiefelsym.systems import derivative

from _h79_helpers import (L_reduced, monopole, quartic_potential, F_Omega, H_neum_k, dim_V, dot, euler_ss_point,
                          euler_ss_tangent, flow_No, jacobian_along, perelomov_functions, tangent_spanning_set,
                          yang_mills_field)

SPHERE = admissible(n_max=5, n_min=2, r_max=1, condition="r = 1")
ALL = admissible(n_max=5)
R2 = admissible(n_max=5, n_min=2, r_min=2, r_max=2, condition="r = 2")
N3R2 = admissible(n_max=3, n_min=3, r_min=2, r_max=2, stated_n_max=3, condition="n = 3, r = 2")


@claim("n79-ym-field-isospectral-order", fails_at=lambda n, r: n >= 3, erratum="false twin (numpy: indep.py.in)", kind="id", sizes=SPHERE, paper=("YM",))
def t1(s):
    """Twin of h79-ym-field-isospectral: dF/dt = [F_Ω, Ω] (order swapped).  False for n ≥ 3 (at n = 2, F_Ω = 0)."""
    z = euler_ss_point(s)
    v = euler_ss_tangent(s, z)
    dF = derivative(s, lambda t, w: F_Omega(w["Om"], w["e"]), z, v)
    return {"dF/dt - [F, Omega]": dF - comm(F_Omega(z["Om"], z["e"]), z["Om"])}


@claim("n79-ym-mag6-speed-sign", fails_at=lambda n, r: True, erratum="false twin (numpy: indep.py.in)", kind="id", sizes=SPHERE, paper=("YM", "mag6"))
def t2(s):
    """Twin of h79-ym-mag6-reduced: ((e, Ae) − (ė, ė)) in place of ((e, Ae) + (ė, ė)).  False for n ≥ 2."""
    z = euler_ss_point(s)
    v = euler_ss_tangent(s, z)
    Om, e = z["Om"], z["e"]
    edot = Om @ e
    edd = derivative(s, lambda t, w: w["Om"] @ w["e"], z, v)
    rhs = s.A @ e - (dot(s, e, s.A @ e) - dot(s, edot, edot)) * e + F_Omega(Om, e) @ edot
    return {"(mag6)": edd - rhs}


@claim("n79-ym-field-conjugation-order", fails_at=lambda n, r: 2 <= r < n, erratum="false twin (numpy: indep.py.in)", kind="id", sizes=ALL, paper=("YM", "No"))
def t3(s):
    """Twin of h79-ym-field-conjugation-kappa: dF/dt = [F, Φ]."""
    flow = s.dirac_flow(H_neum_k)
    F = yang_mills_field(s)
    return {"dF/dt - [F, Phi]": s.d(yang_mills_field, flow) - comm(F, s.Phi)}


@claim("n79-mag-force-plus", fails_at=lambda n, r: n >= 3, erratum="false twin (numpy: indep.py.in)", kind="id", sizes=R2, paper=("mag-euk", "mag-nor", "twisted"))
def t4(s):
    """Twin of h79-mag-force-every-kappa: the force +ε(I − XXᵀ)PJ."""
    flow = twisted.flow(s, H_neum_k)
    plain = flow_No(s, s.kappa)
    J = twisted.magnetic_matrix(s)
    force = s.eps * ((s.In - s.X @ s.X.T) @ s.P @ J)
    return {"dX/dt": flow.Xdot - plain["X"], "dP/dt": flow.Pdot - (plain["P"] + force)}


@claim("n79-mag-grass-monopole-plus", fails_at=lambda n, r: True, erratum="false twin (numpy: indep.py.in)", kind="id", sizes=N3R2, paper=("neum-gras-mag", "YM"),
       equivariance="e_3 = e_1 x e_2 is read from coordinates; (g a) x (g b) = det(g) g (a x b) for g in O(3)")
def t5(s):
    """Twin of h79-mag-grass-monopole-n3: charge +ε."""
    return monopole(s, 1)




@claim("n79-perelomov-det-zero", fails_at=lambda n, r: True, erratum="false twin (numpy: indep.py.in)", kind="id", sizes=ALL, paper=("perelomov",))
def t8(s):
    """Twin of h79-perelomov-cayley-hamilton: e_n(𝓛(λ)) = det 𝓛(λ) = 0."""
    n = int(s.n)
    L = s.lam * s.Phi + s.X @ s.X.T - s.lam * s.lam * s.A
    return {"e_n(L)": elementary(s, L, n)[n]}


@claim("n79-ym-reduced-integrals-plus-a", fails_at=lambda n, r: True, erratum="false twin (numpy: indep.py.in)", kind="pb", sizes=SPHERE, paper=("YM", "perelomov"))
def t9(s):
    """Twin of h79-ym-reduced-integrals: +λ²A in 𝓛."""
    z = euler_ss_point(s)
    v = euler_ss_tangent(s, z)
    out = {}
    for k in (2, 3):
        def f(t, w, k=k):
            L = L_reduced(t, w, lam_sign=-1)
            M = L
            for _ in range(k - 1):
                M = M @ L
            return t.tr(M)
        out[f"d/dt tr L^{k}"] = derivative(s, f, z, v)
    return out


@claim("n79-quartic-duality-sign", fails_at=lambda n, r: r < n, erratum="false twin (numpy: indep.py.in)", kind="id", sizes=ALL, paper=("quartic",))
def t10(s):
    """Twin of h79-quartic-potential-duality: V(π) = tr(NA²) + tr(NANA)."""
    pi = s.X @ s.X.T
    N = s.In - pi
    return {"V(pi) - (tr N A^2 + tr NANA)": quartic_potential(s, pi) - (s.tr(N @ s.A @ s.A) + s.tr(N @ s.A @ N @ s.A))}
