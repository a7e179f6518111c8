"""s81 hidden2 (h81b): ten statements of Fedorov & Jovanović not stated by the catalog, each true.

Derivations by hand are in each docstring; numpy checks (no stiefelsym) in indep.py.in.
The false twins (one change each) are in negatives.py.
"""
from __future__ import annotations

from stiefelsym import Rank, admissible, block, claim, comm, twisted
from stiefelsym.systems import complex_point, derivative, double_point, realify_real

SMALL = admissible(n_max=4)
R2 = admissible(n_max=4, r_min=2, r_max=2, condition="r = 2 (the twisted form of Appendix 1)")
R_GE_2 = admissible(n_max=4, r_min=2, condition="r >= 2")
TWO_R_LE_N = admissible(n_max=5, where=lambda n, r: 2 * r <= n, condition="n >= 2r")


# ---------------------------------------------------------------- metric realization (cond_XP2)

def H_A(t):
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


def metric_constraints(s):
    C1, C2 = s.fresh("r", "r"), s.fresh("r", "r")
    return (lambda t: t.tr(C1 @ t.X.T @ t.X),
            lambda t: t.tr(C2 @ (t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X)))


def generic_function(s):
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return lambda t: t.tr(U.T @ t.X) * t.tr(W.T @ t.P) + t.tr(t.P.T @ t.A @ t.P) + t.tr(U.T @ t.P)


@claim("h81b-metric-leaf-casimirs", paper=("cond_XP2",), kind="pb", section="3", realization="metric",
       sizes=SMALL)
def metric_leaf_casimirs(s):
    """§3, SO(r)-invariant metrics: 'the geodesic flow ... restricted to the symplectic leaf (cond_XP2)' of the
    Dirac bracket {,}_A defined by the constraints XᵀX = I, XᵀA⁻¹P + PᵀA⁻¹X = 0.  By construction of a Dirac
    bracket, every constraint function c is a Casimir: {c, f}_A = {c,f} − {c,c_k}C^{kl}{c_l,f} = 0 since
    {c_j, c_k}C^{kl} = δ_j^l.  Tested with tr(C1 XᵀX), tr(C2 (XᵀA⁻¹P + PᵀA⁻¹X)) and a generic cubic f."""
    c1, c2 = metric_constraints(s)
    f = generic_function(s)
    return {"{tr C1 X^T X, f}_A": s.bracket(c1, f), "{tr C2 (X^T A^-1 P + P^T A^-1 X), f}_A": s.bracket(c2, f)}


@claim("h81b-metric-positions-commute", paper=("cond_XP2", "A_XP"), kind="pb", section="3",
       realization="metric", sizes=SMALL)
def metric_positions_commute(s):
    """For the Dirac bracket of (cond_XP2), functions of X alone commute: {tr UᵀX, tr WᵀX}_A = 0.  Hand: the
    ambient brackets {f, g} = 0 and {f, c1} = 0 (c1 = XᵀX has no P); the constraint matrix is [[0, B], [−Bᵀ, D]]
    with B = {c1, c2} invertible, so its inverse has a zero (2,2) block, and the correction
    −{f, c2}(C⁻¹)_{22}{c2, g} vanishes."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return {"{tr U^T X, tr W^T X}_A": s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.X))}


@claim("h81b-metric-neumann-multiplier", paper=("cond_XP2", "A_XP", "Neumann_potential"), kind="id", section="3",
       realization="metric", sizes=SMALL)
def metric_neumann_multiplier(s):
    """The Neumann potential added to the A-metric (the (A_XP) realization): the Dirac flow of
    H = ½tr(PᵀA⁻¹P) + ½tr(XᵀAX) on (cond_XP2) is Ẋ = A⁻¹P, Ṗ = −AX + XΛ with Λ symmetric and
    ΛM + MΛ + 2PᵀA⁻²P − 2I_r = 0, M = XᵀA⁻¹X.  Hand: Ẋ = H_P − A⁻¹XΠ with ΠM + MΠ = H_PᵀX + XᵀH_P =
    PᵀA⁻¹X + XᵀA⁻¹P = 0, so Π = 0; d/dt(XᵀA⁻¹P + PᵀA⁻¹X) = 2PᵀA⁻²P + XᵀA⁻¹(−AX + XΛ) + (…)ᵀ
    = 2PᵀA⁻²P − 2I + MΛ + ΛM = 0 (for the potential alone Λ = M⁻¹)."""
    H = lambda t: H_A(t) + t.tr(t.X.T @ t.A @ t.X) / 2
    flow = s.dirac_flow(H)
    X, P = s.X, s.P
    F = flow.Pdot + s.A @ X
    Lam = X.T @ F
    M = X.T @ s.Ainv @ X
    return {
        "dX/dt - A^-1 P": flow.Xdot - s.Ainv @ P,
        "dP/dt + AX - X Lambda": F - X @ Lam,
        "Lambda symmetric": Lam - Lam.T,
        "Lambda M + M Lambda + 2 P^T A^-2 P - 2 I": Lam @ M + M @ Lam + 2 * (P.T @ s.Ainv @ s.Ainv @ P) - 2 * s.Ir,
    }


# ---------------------------------------------------------------- double Neumann system (D-eq)

def flow_double(t, z):
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    Lam = X.T @ t.A @ Y - Xd.T @ Yd
    return {"X": Xd, "Y": Yd, "Xdot": -(t.A @ X) + X @ Lam.T, "Ydot": -(t.A @ Y) + Y @ Lam}


def M_double(t, z):
    return z["Ydot"] @ z["X"].T - z["Y"] @ z["Xdot"].T


def YXt(t, z):
    return z["Y"] @ z["X"].T


@claim("h81b-double-prep", paper=("D-eq", "D-L", "prep"), kind="id", section="A2", sizes=SMALL)
def double_prep(s):
    """The (prep) of the double Neumann system: with M = ẎXᵀ − YẊᵀ (the gl(n) Noether quantity of X ↦ gX,
    Y ↦ g⁻ᵀY, which leaves tr ẊᵀẎ and XᵀY invariant) and the projector YXᵀ, along (D-eq):
    dM/dt = ŸXᵀ − YẌᵀ = (−AY + YΛ)Xᵀ − Y(−AX + XΛᵀ)ᵀ = [YXᵀ, A];
    d(YXᵀ)/dt = ẎXᵀ + YẊᵀ = [M, YXᵀ] (using XᵀY = I, ẊᵀY + XᵀẎ = 0).  At X = Y it is (prep) of (NE_XP)."""
    z = double_point(s)
    v = flow_double(s, z)
    return {"dM/dt - [YX^T, A]": derivative(s, M_double, z, v) - comm(YXt(s, z), s.A),
            "d(YX^T)/dt - [M, YX^T]": derivative(s, YXt, z, v) - comm(M_double(s, z), YXt(s, z))}


@claim("h81b-double-lax-n", paper=("D-eq", "D-L", "Neumann_LA", "LA1", "LA2"), kind="lax", section="A2", sizes=SMALL)
def double_lax_n(s):
    """The n×n Lax pair (LA1)–(LA2) extends to the double system (as the paper extends (LA3)):
    𝓛(λ) = λM + YXᵀ − λ²A, 𝓐(λ) = M − λA, d𝓛/dt = [𝓐, 𝓛] along (D-eq).  Hand: d𝓛/dt = λ[YXᵀ, A] + [M, YXᵀ]
    (h81b-double-prep) and [M − λA, λM + YXᵀ − λ²A] = [M, YXᵀ] − λ[A, YXᵀ]."""
    z = double_point(s)
    v = flow_double(s, z)
    lam = s.lam
    L = lambda t, w: lam * M_double(t, w) + YXt(t, w) - lam * lam * t.A
    Am = M_double(s, z) - lam * s.A
    return {"dL/dt - [A, L]": derivative(s, L, z, v) - comm(Am, L(s, z))}


# ---------------------------------------------------------------- complex Stiefel variety W(n, r)

def flow_complex(t, z):
    A = realify_real(t, t.A)
    Z, Zd = z["Z"], z["Zdot"]
    Lam = Z.T @ A @ Z - Zd.T @ Zd      # realified: M.T is the conjugate transpose
    return {"Z": Zd, "Zdot": -(A @ Z) + Z @ Lam}


def Phi_c(t, z):
    return z["Zdot"] @ z["Z"].T - z["Z"] @ z["Zdot"].T


def ZZs(t, z):
    return z["Z"] @ z["Z"].T


@claim("h81b-complex-prep", paper=("W-eq", "W-L", "prep"), kind="id", section="A2", sizes=admissible(n_max=3))
def complex_prep(s):
    """(prep) on W(n, r): with the anti-Hermitian Φ_c = ŻZ* − ZŻ* and the Hermitian projector ZZ*
    (Z* = Z̄ᵀ; realified, the plain transpose), along (W-eq): dΦ_c/dt = Z̈Z* − ZZ̈* = (−AZ + ZΛ)Z* − Z(−AZ + ZΛ)*
    = [ZZ*, A] since Λ = Λ* (W-L); d(ZZ*)/dt = ŻZ* + ZŻ* = [Φ_c, ZZ*] (Z*Z = I, Z*Ż + Ż*Z = 0)."""
    z = complex_point(s)
    v = flow_complex(s, z)
    A = realify_real(s, s.A)
    return {"dPhi_c/dt - [ZZ*, A]": derivative(s, Phi_c, z, v) - comm(ZZs(s, z), A),
            "d(ZZ*)/dt - [Phi_c, ZZ*]": derivative(s, ZZs, z, v) - comm(Phi_c(s, z), ZZs(s, z))}


@claim("h81b-complex-lax-traces", paper=("W-eq", "W-L", "Neumann_LA", "perelomov"), kind="pb", section="A2",
       sizes=admissible(n_max=3))
def complex_lax_traces(s):
    """The integrals (perelomov) on W(n, r): tr 𝓛_c(λ)^k, 𝓛_c = λΦ_c + ZZ* − λ²A, are conserved along (W-eq)
    (k = 2, 3): d𝓛_c/dt = [Φ_c − λA, 𝓛_c] by h81b-complex-prep, and tr of a commutator times a power vanishes."""
    z = complex_point(s)
    v = flow_complex(s, z)
    lam = s.lam
    realify_real(s, s.A)                  # (the realified A, traced as the trial wrote it)

    def L(t, w):
        return lam * Phi_c(t, w) + ZZs(t, w) - lam * lam * realify_real(t, t.A)

    return {"d tr L^2/dt": derivative(s, lambda t, w: (L(t, w) @ L(t, w)).trace(), z, v),
            "d tr L^3/dt": derivative(s, lambda t, w: (L(t, w) @ L(t, w) @ L(t, w)).trace(), z, v)}


# ---------------------------------------------------------------- twisted (magnetic) bracket

@claim("h81b-twisted-positions", paper=("twisted", "mag-euk"), kind="pb", section="A1", sizes=R2)
def twisted_positions(s):
    """ω_ε = ω + επ*ω_mag changes only the brackets of momenta: functions of X alone still commute, and the flow of a
    potential V(X) (here ½tr XᵀAX) is the untwisted Dirac flow.  Hand: ambient {f, g}_ε = {f, g}₀ − ε tr(f_Pᵀ g_P F)
    equals {f, g}₀ whenever f_P = 0 or g_P = 0; the constraint matrix C_ε = [[0, B], [−Bᵀ, D_ε]] keeps
    B = {c1, c2} (c1 = XᵀX has no P), so (C_ε⁻¹)_{22} = 0 and (C_ε⁻¹)_{12} = (C₀⁻¹)_{12}: the Dirac corrections
    of {f(X), g(X)} and of {z, V} are the untwisted ones."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    V = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2
    tw, d = twisted.flow(s, V), s.dirac_flow(V)
    return {"{tr U^T X, tr W^T X}_eps": twisted.bracket(s, lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.X)),
            "X' twisted - X' untwisted": tw.Xdot - d.Xdot,
            "P' twisted - P' untwisted": tw.Pdot - d.Pdot}


@claim("h81b-twisted-positions-any-F", paper=("twisted",), kind="pb", section="A1", sizes=R_GE_2)
def twisted_positions_any_F(s):
    """The same for ω + ε Σ F_jk de_j∧de_k with a generic skew field strength F ∈ so(r), r ≥ 2."""
    F = s.generic("Fmag", "r", "r", "skew")
    V = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2
    tw, d = twisted.flow(s, V, F), s.dirac_flow(V)
    return {"X' twisted - X' untwisted": tw.Xdot - d.Xdot,
            "P' twisted - P' untwisted": tw.Pdot - d.Pdot}


# ---------------------------------------------------------------- a rank with a kernel certificate

def phi_jacobian_and_kernel(s):
    n, r = int(s.n), int(s.r)
    J = s.mat(s.jacobian(lambda t: [t.Phi], symmetric=False))
    X, P = s.X, s.P
    cols = []
    m = 2 * r
    for a in range(m):
        for b in range(a, m):
            S = s.mat([[1 if (i, j) in ((a, b), (b, a)) else 0 for j in range(m)] for i in range(m)], ("r+r", "r+r"))
            dW = block([[P, -X]]) @ S           # W J S, W = (X P), J = [[0, -I], [I, 0]]
            dX, dP = dW[0:n, 0:r], dW[0:n, r:m]
            cols.append([dX[i, j] for i in range(n) for j in range(r)] + [dP[i, j] for i in range(n) for j in range(r)])
    K = s.mat([[cols[c][k] for c in range(len(cols))] for k in range(2 * n * r)], ("coords", "sp"))
    return J, K


@claim("h81b-phi-ambient-rank", paper=("momentum_map", "2r-integrals", "ddim"), kind="dim", section="2",
       sizes=TWO_R_LE_N)
def phi_ambient_rank(s):
    """Φ = PXᵀ − XPᵀ = WJWᵀ (W = (X P), J = [[0, −I], [I, 0]]) on the ambient T*M_{n,r}: its image is the
    variety of skew matrices of rank 2r, of dimension 2nr − r(2r + 1), and the fibres are the Sp(2r) orbits
    W ↦ Wg.  So the ambient Jacobian of Φ has generic rank 2nr − r(2r + 1) (n ≥ 2r); kernel certificate:
    the r(2r + 1) fields δW = WJS, S ∈ Sym(2r) (δΦ = W(JSJ + JSᵀJᵀ)Wᵀ = 0)."""
    n, r = int(s.n), int(s.r)
    J, K = phi_jacobian_and_kernel(s)
    return {"rank dPhi": Rank(J, 2 * n * r - r * (2 * r + 1), kernel=K)}
