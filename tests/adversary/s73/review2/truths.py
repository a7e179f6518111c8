# ruff: noqa
"""Stop 73, second review: true statements on the settings where the early rational point of the exact method is
new (charts other than the Cayley chart: the equivariant chart, the diagonal chart, the complex point, the second
point, the metric realization, the twisted flows, coordinates of R^r and R^n, resolvents, r = n).  Each must be
proved (or checked) by exact, never `fails`."""
from stiefelsym import admissible, claim, comm, det, twisted
from stiefelsym.systems import complex_point, coupled_point, double_point, re_trace, ctranspose

SMALL = admissible(n_max=4)
R_LT_N = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")
R_IS_N = admissible(n_max=4, r_is_n=True, condition="r = n")
R_IS_2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("rv2-metric-constraint", paper="cond_XP2", kind="id", sizes=SMALL, realization="metric")
def metric_constraint(s):
    """True on (cond_XP2): XᵀA⁻¹P + PᵀA⁻¹X = 0, XᵀX = I, and its entry (1,1) read alone."""
    M = s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X
    return {"cond2": M, "XtX": s.X.T @ s.X - s.Ir, "M11": M[0, 0]}


@claim("rv2-metric-energy", paper="cond_XP2", kind="pb", sizes=SMALL, realization="metric")
def metric_energy(s):
    """True: H = ½tr PᵀP + ½tr XᵀAX is conserved by its own Dirac flow on (cond_XP2)."""
    return {"dH/dt": s.d(H, s.dirac_flow(H))}


@claim("rv2-xxt-r-n", paper="cond_XP", kind="id", sizes=R_IS_N)
def xxt_r_n(s):
    """True at r = n: XXᵀ = Iₙ, det(X)² = 1 (both components of O(n))."""
    n = int(s.n)
    d = det(s, s.mat([[s.X[i, j] for j in range(n)] for i in range(n)], ("n", "n")))
    return {"XXt": s.X @ s.X.T - s.In, "det^2 - 1": d * d - 1}


@claim("rv2-second-point", paper="cond_XP", kind="id", sizes=SMALL)
def second_point(s):
    """True: the second point (Y, Q) lies on T*V; tr(XᵀY)² ≤ ... no: YᵀY = I, YᵀQ + QᵀY = 0, read entry (0,0)."""
    return {"YtY": s.Y.T @ s.Y - s.Ir, "YtQ": s.Y.T @ s.Q + s.Q.T @ s.Y, "Y00": (s.Y.T @ s.Y)[0, 0] - 1}


@claim("rv2-complex-constraints", paper="W-L", kind="id", sizes=SMALL)
def complex_constraints(s):
    """True: Z*Z = I_r and Z*Ż + Ż*Z = 0 at the complex point (realified); Re tr Z*Z = r."""
    z = complex_point(s)
    Z, V = z["Z"], z["Zdot"]
    Zs, Vs = Z.T, V.T       # the transpose of a realified matrix is its conjugate transpose
    return {"Z*Z": Zs @ Z - s.realify(s.Ir, s.Ir - s.Ir), "Z*V+V*Z": Zs @ V + Vs @ Z,
            "Re tr Z*Z - r": re_trace(s, Zs @ Z) - s.r}


@claim("rv2-double-point", paper="D0", kind="id", sizes=SMALL)
def double(s):
    """True: XᵀY = I_r and ẊᵀY + XᵀẎ = 0 at the double point."""
    z = double_point(s)
    return {"XtY": z["X"].T @ z["Y"] - s.Ir, "d": z["Xdot"].T @ z["Y"] + z["X"].T @ z["Ydot"]}


@claim("rv2-resolvent-coordinates", paper="cond_XP", kind="id", sizes=SMALL)
def resolvent_coords(s):
    """True: R(λ)_{ii} = 1/(λ − a_i) and R(λ)_{01} = 0 (A diagonal), read entry by entry."""
    R = s.resolvent(s.lam)
    out = {}
    for i in range(int(s.n)):
        out[f"R{i}{i}"] = R[i, i] * (s.lam - s.a[i]) - 1
    if int(s.n) > 1:
        out["R01"] = R[0, 1]
    return out


@claim("rv2-twisted-energy", paper="twisted", kind="pb", sizes=R_IS_2)
def twisted_energy(s):
    """True: H is conserved along the flow of the twisted form ω + ε de₁∧de₂ (r = 2)."""
    return {"dH/dt": s.d(H, twisted.flow(s, H))}


@claim("rv2-prep-psi-coords", paper="prep", kind="id", sizes=SMALL)
def prep_psi_coords(s):
    """True: dΦ/dt = [XXᵀ, A] along the Neumann flow, and dΨ₀₀/dt = 0 (Ψ skew: Ψ₀₀ = 0), read by entry."""
    flow = s.dirac_flow(H)
    return {"prep": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A), "dPsi00": s.d(lambda t: t.Psi[0, 0], flow)}


@claim("rv2-pencil-no-point", paper="cond_XP", kind="id", sizes=SMALL)
def pencil_no_point(s):
    """True (reads no point): (λI − A)R(λ) = I and R(λ) − R(μ) = (μ − λ)R(λ)R(μ)."""
    mu = s.scalar("mu")
    Rl, Rm = s.resolvent(s.lam), s.resolvent(mu)
    return {"res": (s.In * s.lam - s.A) @ Rl - s.In, "resid": Rl - Rm - (Rm @ Rl) * (mu - s.lam)}
