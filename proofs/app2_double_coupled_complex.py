"""Appendix 2. Double, coupled and complex Neumann systems: the Lagrangian systems, their flows, conserved quantities and Lax pairs."""
from __future__ import annotations

from fractions import Fraction

from stiefelsym import Count, admissible, block, claim, comm, twisted  # noqa: F401
from stiefelsym.systems import (complex_coordinates, complex_point, coupled_point, ctranspose,
                                derivative, double_point, euler_lagrange, hermitian_entries,
                                re_trace, real_complex_point, real_coordinates, realify_real, stiefel_pairs_flow)

from .sec8_dual_lax_pair import A_dual_euclidean, L_dual

SECTION = "A2"

#: the coupled and complex systems: on the exact method's equivariant chart the second point (Y, Q)
#: and the complex point are Cayley points with one symbolic r x r inverse, and the multipliers of the
#: coupled flow have closed forms; the symbolic budget of each claim (exact_max_n, exact_max_r) is
#: where that stays within a few seconds.  The Lax pairs differentiated by the derivative step are block
#: matrices of whole copies of R^n or R^r (no splitting of R^n), so they go to that chart too, where the
#: resolvent is one symbolic inverse of lambda I - A (A generic with A22 diagonal); the printed pairs that
#: fail are refuted by their witnesses, so SYMBOLIC_N_MAX keeps their own budget at n = 1
SYMBOLIC_N_MAX = 1


def _scalar_block(s, c):
    """c·I_r."""
    return s.scalar_matrix(c, s.r, "r")


def _zero_r(s):
    return s.zeros(s.r, s.r, ("r", "r"))


def resolvent_flipped(s):
    """(I_n − λA)⁻¹ = λ⁻¹(λ⁻¹I_n − A)⁻¹, as printed in (LA3*D) and (LA3*)."""
    return s.resolvent(s.q(1) / s.lam) / s.lam


# ==== the rank r double Neumann system ============================================================

def T_double(t, v):
    """(D-Lag), the kinetic part: tr(ẊᵀẎ)."""
    return t.tr(v["X"].T @ v["Y"])


def U_double(t, q):
    """(D-Lag), the potential: tr(XᵀAY); L = T − U."""
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    """(D0): XᵀY − I_r (all r² entries are constraints)."""
    return [q["X"].T @ q["Y"] - t.Ir]


def Lambda_double(t, z):
    """(D-L): Λ = XᵀAY − ẊᵀẎ."""
    return z["X"].T @ t.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]


def flow_double(t, z):
    """(D-eq) as a first-order system: Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ."""
    Lam = Lambda_double(t, z)
    return {"X": z["Xdot"], "Y": z["Ydot"],
            "Xdot": -(t.A @ z["X"]) + z["X"] @ Lam.T, "Ydot": -(t.A @ z["Y"]) + z["Y"] @ Lam}


def double_accelerations(s, z):
    """Ẍ, Ÿ of the Euler–Lagrange equations of (D-Lag) with the constraints (D0) at z."""
    acc, _ = euler_lagrange(s, T_double, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return acc


def L_dual_double(t, z, flipped):
    """(LA3*D): 𝓛(λ) with R = (λI_n − A)⁻¹ on the diagonal and ``flipped`` off the diagonal."""
    R = t.resolvent(t.lam)
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    return block([[-(X.T @ R @ Yd), -(X.T @ flipped @ Y)],
                  [t.Ir + Xd.T @ flipped @ Yd, Xd.T @ R @ Y]])


def A_dual_double(t, z):
    """(LA3*D): 𝓐(λ) = [[0, I_r], [Λ − λI_r, 0]]."""
    return block([[_zero_r(t), t.Ir], [Lambda_double(t, z) - _scalar_block(t, t.lam), _zero_r(t)]])


def double_lax_residual(s, flipped):
    z = double_point(s)
    L = lambda t, w: L_dual_double(t, w, flipped(t))
    return derivative(s, L, z, flow_double(s, z)) - comm(L(s, z), A_dual_double(s, z))


@claim("double-neumann-flow", paper=("D-Lag", "D0", "D-eq", "D-L"), kind="id", exact_max_n=5,
       exact_max_r={6: 5, 7: 5},
       statement=r"L=\tr(\dot X^T\dot Y)-\tr(X^TAY),\ X^TY=\mathbf I_r:\quad "
                 r"\ddot X=-AX+X\Lambda^T,\ \ddot Y=-AY+Y\Lambda,\ \Lambda=X^TAY-\dot X^T\dot Y")
def double_neumann_flow(s):
    """The Euler–Lagrange equations of the Lagrangian (D-Lag) with the holonomic constraints (D0), derived with r×r multipliers, are the printed (D-eq) with Λ of (D-L), and (D-eq) keeps XᵀY = I_r."""
    z = double_point(s)
    acc, printed = double_accelerations(s, z), flow_double(s, z)
    velocity_constraint = lambda t, w: w["Xdot"].T @ w["Y"] + w["X"].T @ w["Ydot"]
    return {
        "X'' (D-Lag) - (D-eq)": acc["X"] - printed["Xdot"],
        "Y'' (D-Lag) - (D-eq)": acc["Y"] - printed["Ydot"],
        "d(X^T Y)/dt": velocity_constraint(s, z),
        "d^2(X^T Y)/dt^2 along (D-eq)": derivative(s, velocity_constraint, z, printed),
    }


@claim("double-neumann-dual-lax", nature="formula", paper=("dual-D", "LA3*D", "D-eq", "D-L"), kind="lax", exact_max_n=2,
       fails_at=lambda n, r: True,
       place="the off-diagonal blocks of 𝓛(λ) in (5) §10, Theorem 10.1",
       erratum="""Theorem 10.1: with (I_n − λA)^{-1} in the off-diagonal blocks of 𝓛(λ), as printed in (5) §10,
       the equations (3) §10 do not imply d𝓛/dt = [𝓛, 𝓐].  They do with (λI_n − A)^{-1} in all four blocks, as
       in (2) §8 of Theorem 8.1, which (5) §10 extends: 𝓛(λ) = [[−XᵀRẎ, −XᵀRY], [I_r + ẊᵀRẎ, ẊᵀRY]],
       R = (λI_n − A)^{-1}.""",
       statement=r"\tfrac{d}{dt}\mathcal L(\lambda)=[\mathcal L(\lambda),\mathcal A(\lambda)],\ "
                 r"\mathcal L=\begin{pmatrix}-X^T(\lambda\mathbf I_n-A)^{-1}\dot Y&-X^T(\mathbf I_n-\lambda A)^{-1}Y\\"
                 r"\mathbf I_r+\dot X^T(\mathbf I_n-\lambda A)^{-1}\dot Y&\dot X^T(\lambda\mathbf I_n-A)^{-1}Y\end{pmatrix},\ "
                 r"\mathcal A=\begin{pmatrix}0&\mathbf I_r\\\Lambda-\lambda\mathbf I_r&0\end{pmatrix}")
def double_neumann_dual_lax(s):
    """Theorem dual-D: the equations (D-eq) imply the 2r×2r Lax equation (LA3*D) with the printed 𝓛(λ), whose off-diagonal blocks contain (I_n − λA)⁻¹, and 𝓐(λ)."""
    return {"d𝓛(λ)/dt − [𝓛(λ), 𝓐(λ)]": double_lax_residual(s, resolvent_flipped)}


@double_neumann_dual_lax.claim.correction(
    "(5) §10: (λI_n − A)⁻¹ in place of (I_n − λA)⁻¹ in the off-diagonal blocks",
    exact_max_r={3: 3, 4: 3, 5: 2, 6: 1, 7: 1}, blocks_of="𝓛(λ) in (5) §10")
def double_neumann_dual_lax_corrected(s):
    return {"d𝓛(λ)/dt − [𝓛(λ), 𝓐(λ)]": double_lax_residual(s, lambda t: t.resolvent(t.lam))}


def double_lax_at_the_diagonal(s, flipped):
    """(LA3*D) at X = Y ∈ V(n, r), Ẋ = Ẏ = P, against (LA3), (LA4) of Theorem DUAL for (NE_XP)."""
    z = {"X": s.X, "Y": s.X, "Xdot": s.P, "Ydot": s.P}
    return {"𝓛(λ) − 𝓛*_neum(λ)": L_dual_double(s, z, flipped(s)) - L_dual(s),
            "𝓐(λ) − 𝓐*_neum(λ)": A_dual_double(s, z) - A_dual_euclidean(s)}


@claim("double-neumann-dual-lax-extends-la3", nature="formula", paper=("dual-D", "LA3*D", "LA3", "LA4"), kind="id", exact_max_n=3,
       fails_at=lambda n, r: True,
       place="the off-diagonal blocks of 𝓛(λ) in (5) §10, Theorem 10.1",
       erratum="""The sentence before Theorem 10.1 says that (5) §10 extends the Lax representation (1) §8: at
       X = Y, Ẋ = Ẏ = P the printed 𝓛(λ) of (5) §10 is not 𝓛*_neum(λ) of (2) §8, because of the (I_n − λA)^{-1}
       in its off-diagonal blocks; with (λI_n − A)^{-1} there (the correction of Theorem 10.1) it is, and 𝓐(λ) is
       the 𝓐*_neum(λ) of (3) §8 for the Neumann system (5) §5.""",
       statement=r"X=Y,\ \dot X=\dot Y=P:\quad \mathcal L(\lambda)=\mathcal L^*_{neum}(\lambda),\ "
                 r"\mathcal A(\lambda)=\mathcal A^*_{neum}(\lambda)=\begin{pmatrix}0&\mathbf I_r\\"
                 r"\Lambda-\lambda\mathbf I_r&0\end{pmatrix}")
def double_neumann_dual_lax_extends_la3(s):
    """The 2r×2r Lax pair (LA3*D) extends (LA3): at X = Y ∈ V(n, r), Ẋ = Ẏ = P, its matrices 𝓛(λ), 𝓐(λ) are 𝓛*_neum(λ) of (LA3) and 𝓐*_neum(λ) of (LA4) for the Euclidean Neumann system (NE_XP)."""
    return double_lax_at_the_diagonal(s, resolvent_flipped)


@double_neumann_dual_lax_extends_la3.claim.correction(
    "(5) §10: (λI_n − A)⁻¹ in place of (I_n − λA)⁻¹ in the off-diagonal blocks",
    exact_max_r={4: 4, 5: 5, 6: 6, 7: 7}, blocks_of="𝓛(λ) in (5) §10")
def double_neumann_dual_lax_extends_la3_corrected(s):
    return double_lax_at_the_diagonal(s, lambda t: t.resolvent(t.lam))


@claim("double-neumann-momentum", paper=("dual-D", "D-Lag", "D0", "D-eq"), kind="pb", exact_max_n=5,
       exact_max_r={6: 5, 7: 5},
       statement=r"\tfrac{d}{dt}\left(X^T\dot Y-Y^T\dot X\right)=0\ \text{along (D-eq)};\ "
                 r"(X,Y)\mapsto(XR^T,YR^{-1})\ \text{preserves (D-Lag), (D0)},\ "
                 r"\tfrac{d}{dt}\left(X^T\dot Y-\dot X^TY\right)=0")
def double_neumann_momentum(s):
    """The matrix XᵀẎ − YᵀẊ is conserved along (D-eq); the action (X, Y) ↦ (XRᵀ, YR⁻¹), R ∈ GL(r), leaves (D-Lag) and (D0) invariant, and its Noether momentum N = XᵀẎ − ẊᵀY is conserved too (claim double-neumann-printed-integral compares the two)."""
    z = double_point(s)
    flow = flow_double(s, z)
    xi = s.generic("xi", "r", "r")
    action = {"X": z["X"] @ xi.T, "Y": -(z["Y"] @ xi), "Xdot": z["Xdot"] @ xi.T, "Ydot": -(z["Ydot"] @ xi)}
    L = lambda t, w: (T_double(t, {"X": w["Xdot"], "Y": w["Ydot"]}) - U_double(t, {"X": w["X"], "Y": w["Y"]}))
    return {
        "d(X^T Y' - Y^T X')/dt": derivative(s, lambda t, w: w["X"].T @ w["Ydot"] - w["Y"].T @ w["Xdot"], z, flow),
        "d(X^T Y' - X'^T Y)/dt": derivative(s, lambda t, w: w["X"].T @ w["Ydot"] - w["Xdot"].T @ w["Y"], z, flow),
        "L along the GL(r)-action": derivative(s, L, z, action),
        "X^T Y along the GL(r)-action": derivative(s, lambda t, w: w["X"].T @ w["Y"], z, action),
    }


@claim("double-neumann-printed-integral", paper=("dual-D", "D0", "D-eq"), kind="id",
       statement=r"X^T\dot Y-Y^T\dot X=\tfrac12\big(N+N^T\big),\quad N=X^T\dot Y-\dot X^TY")
def double_neumann_printed_integral(s):
    """The matrix integral XᵀẎ − YᵀẊ printed after Theorem 10.1 is the symmetric part of the GL(r)-momentum N = XᵀẎ − ẊᵀY of the symmetry (X, Y) ↦ (XRᵀ, YR⁻¹) (on the phase space XᵀẎ + ẊᵀY = 0, the derivative of (D0)).  Its antisymmetric part is lost: on the solutions X = Y, Ẋ = Ẏ = P (claim double-neumann-diagonal: they are those of the Neumann system (NE_XP)), the printed matrix is XᵀP − XᵀP = 0, while N is XᵀP − PᵀX = Ψ, the momentum of that system's SO(r)-symmetry.  So the printed matrix is read as a slip for N (see the typographical slips)."""
    z = double_point(s)
    printed = z["X"].T @ z["Ydot"] - z["Y"].T @ z["Xdot"]
    noether = z["X"].T @ z["Ydot"] - z["Xdot"].T @ z["Y"]
    return {"(X^T Y' - Y^T X') - (N + N^T)/2": printed - (noether + noether.T) * Fraction(1, 2)}


@claim("double-neumann-symmetry-group", nature="size", encodes='R ∈ GL(n, ℝ)', paper=("dual-D", "D-eq"), kind="dim", exact_max_n=7,
       sizes=admissible(n_max=5), fails_at=lambda n, r: r != n,
       place="the paragraph after Theorem 10.1",
       erratum="""After Theorem 10.1 the matrix integral XᵀẎ − YᵀẊ is said to come from the GL(n, ℝ)-symmetry
       (X, Y, Ẋ, Ẏ) ↦ (XRᵀ, YR^{-1}, ẊRᵀ, ẎR^{-1}), R ∈ GL(n, ℝ); R multiplies the n × r matrices X, Y on the
       right, so it is r × r, and the integral is r × r too.  Corrected: R ∈ GL(r, ℝ) (claim
       double-neumann-momentum proves the integral conserved and the action a symmetry).  The same sentence
       names XᵀẎ − YᵀẊ as this symmetry's integral: it is conserved, but it is only the symmetric part of the
       symmetry's momentum XᵀẎ − ẊᵀY and vanishes on the solutions X = Y, Ẋ = Ẏ, where the momentum is Ψ
       (claim double-neumann-printed-integral); it is listed among the typographical slips.""",
       statement=r"(X,Y,\dot X,\dot Y)\mapsto(XR^T,YR^{-1},\dot XR^T,\dot YR^{-1}),\ R\in GL(n,\mathbb R):\ "
                 r"\text{size of }R=\text{number of columns of }X")
def double_neumann_symmetry_group(s):
    """The symmetry group printed after Theorem dual-D, GL(n, ℝ), acts on X by X ↦ XRᵀ: R has as many rows as X has
    columns."""
    X = double_point(s)["X"]
    return {"columns of X = size of R": Count(X.shape[1], s.n, "the columns of X; printed: the size n of R ∈ GL(n, ℝ)")}


@double_neumann_symmetry_group.claim.correction("GL(r, ℝ) in place of GL(n, ℝ)")
def double_neumann_symmetry_group_corrected(s):
    X = double_point(s)["X"]
    return {"columns of X = size of R": Count(X.shape[1], s.r, "the columns of X; corrected: the size r of R ∈ GL(r, ℝ)")}


def flow_NE(s):
    """(NE_XP): Ẋ = P, Ṗ = −AX − XPᵀP + XXᵀAX."""
    X, P, A = s.X, s.P, s.A
    return {"X": P, "P": -(A @ X) - X @ P.T @ P + X @ X.T @ A @ X}


@claim("double-neumann-diagonal", paper=("D-eq", "NE_XP"), kind="id",
       statement=r"X=Y,\ \dot X=\dot Y:\quad \ddot X=\ddot Y=-AX-X\dot X^T\dot X+XX^TAX\ \text{(NE\_XP)}")
def double_neumann_contains_the_euclidean_neumann_system(s):
    """At initial conditions X = Y ∈ V(n, r), Ẋ = Ẏ, the Euler–Lagrange equations of (D-Lag), (D0) give Ẍ = Ÿ, so X = Y persists, and Ẍ is the acceleration Ṗ of the Euclidean Neumann system (NE_XP) at (X, P) = (X, Ẋ)."""
    z = {"X": s.X, "Y": s.X, "Xdot": s.P, "Ydot": s.P}
    acc = double_accelerations(s, z)
    return {"X'' - Y''": acc["X"] - acc["Y"], "X'' - (NE_XP)": acc["X"] - flow_NE(s)["P"]}


# ==== the r-coupled Neumann systems ===============================================================

def T_kappa(t, z, kappa):
    """(C-neumann): T_κ = ½tr(PᵀP) − (½ + κ)tr((XᵀP)²) + ½tr(QᵀQ) − (½ + κ)tr((YᵀQ)²)."""
    XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    c = t.q(1, 2) + kappa
    return (t.q(1, 2) * t.tr(z["P"].T @ z["P"]) - c * t.tr(XP @ XP)
            + t.q(1, 2) * t.tr(z["Q"].T @ z["Q"]) - c * t.tr(YQ @ YQ))


def H_coupled(kappa):
    """(C-neumann): H = T_κ + tr(XᵀAY), for κ a function of the scene."""
    return lambda t, z: T_kappa(t, z, kappa(t)) + t.tr(z["X"].T @ t.A @ z["Y"])


def H_perturbed(kappa):
    """The perturbed Hamiltonian H_κ = T_κ + tr(XᵀAY) − 2κ tr(XᵀP YᵀQ)."""
    return lambda t, z: (H_coupled(kappa)(t, z)
                         - 2 * kappa(t) * t.tr(z["X"].T @ z["P"] @ z["Y"].T @ z["Q"]))


FREE_KAPPA = lambda t: t.kappa
NORMAL = lambda t: t.q(0)
EUCLIDEAN = lambda t: t.q(-1, 2)


def coupled_flow(s, H):
    """The flow of H on T*V × T*V with the constraints (cond_XP) of both points, XᵀX = I_r, XᵀP + PᵀX = 0,
    YᵀY = I_r, YᵀQ + QᵀY = 0 (the Hamilton equations with multipliers)."""
    return stiefel_pairs_flow(s, H, coupled_point(s), [("X", "P"), ("Y", "Q")])


def Lambda_Pi_coupled(t, z):
    """(C-L): Λ = ½(XᵀAY + YᵀAX) − PᵀP, Π = ½(XᵀAY + YᵀAX) − QᵀQ."""
    X, Y, P, Q, A = z["X"], z["Y"], z["P"], z["Q"], t.A
    S = (X.T @ A @ Y + Y.T @ A @ X) / 2
    return S - P.T @ P, S - Q.T @ Q


def flow_C_eq(t, z, kappa, Q_Pi=True):
    """(C-eq) with (C-L); ``Q_Pi``: the last term of Q̇ is QΠ as printed (else YΠ)."""
    X, P, Y, Q, A = z["X"], z["P"], z["Y"], z["Q"], t.A
    c = 1 + 2 * kappa
    Lam, Pi = Lambda_Pi_coupled(t, z)
    return {"X": P - c * (X @ P.T @ X),
            "P": -(A @ Y) + c * (P @ X.T @ P) + X @ Lam,
            "Y": Q - c * (Y @ Q.T @ Y),
            "Q": -(A @ X) + c * (Q @ Y.T @ Q) + (Q if Q_Pi else Y) @ Pi}


def coupled_flow_checks(s, Q_Pi):
    z = coupled_point(s)
    derived = coupled_flow(s, H_coupled(FREE_KAPPA))
    printed = flow_C_eq(s, z, s.kappa, Q_Pi)
    kept = derivative(s, lambda t, w: [w["X"].T @ w["X"], w["X"].T @ w["P"] + w["P"].T @ w["X"],
                                       w["Y"].T @ w["Y"], w["Y"].T @ w["Q"] + w["Q"].T @ w["Y"]], z, printed)
    checks = {f"d{k}/dt along the flow of (6) §10 − d{k}/dt by (7) §10": derived[k] - printed[k] for k in ("X", "P", "Y", "Q")}
    checks.update({"d(XᵀX)/dt along (7) §10": kept[0], "d(XᵀP + PᵀX)/dt along (7) §10": kept[1],
                   "d(YᵀY)/dt along (7) §10": kept[2], "d(YᵀQ + QᵀY)/dt along (7) §10": kept[3]})
    return checks


@claim("coupled-neumann-flow", nature="formula", paper=("C-neumann", "C-eq", "C-L"), kind="id", exact_max_n=3,
       exact_max_r={4: 1, 5: 1, 6: 1, 7: 1},
       fails_at=lambda n, r: True,
       place="the last line of (7) §10, the equation for Q̇",
       erratum="""(7) §10: the last term of the equation for Q̇ is printed QΠ; the flow of the Hamiltonian (6) §10
       on T*V × T*V has YΠ there (the multiplier of YᵀY = I_r, as XΛ in the equation for Ṗ), with Π of (8) §10.
       With QΠ the printed system is not the Hamiltonian flow and does not keep YᵀQ + QᵀY = 0.""",
       statement=r"\dot X=P-(1+2\kappa)XP^TX,\ \dot P=-AY+(1+2\kappa)PX^TP+X\Lambda,\ "
                 r"\dot Y=Q-(1+2\kappa)YQ^TY,\ \dot Q=-AX+(1+2\kappa)QY^TQ+Q\Pi,\ "
                 r"\Lambda=\tfrac12(X^TAY+Y^TAX)-P^TP,\ \Pi=\tfrac12(X^TAY+Y^TAX)-Q^TQ")
def coupled_neumann_flow(s):
    """For every κ, the flow of the Hamiltonian (C-neumann) on T*V × T*V with both constraint sets is the printed r-coupled Neumann system (C-eq) with the multipliers (C-L), and (C-eq) keeps both constraint sets."""
    return coupled_flow_checks(s, Q_Pi=True)


@coupled_neumann_flow.claim.correction("(7) §10: YΠ in place of QΠ in the equation for Q̇", exact_max_r={4: 4})
def coupled_neumann_flow_corrected(s):
    return coupled_flow_checks(s, Q_Pi=False)


@claim("coupled-neumann-momentum", paper=("C-eq",), kind="pb", exact_max_n=4,
       exact_max_r={5: 2, 6: 1, 7: 1},
       statement=r"\tfrac{d}{dt}\left(X^TP-P^TX+Y^TQ-Q^TY\right)=0\ \text{along (C-eq)}")
def coupled_neumann_momentum(s):
    """For every κ, the momentum XᵀP − PᵀX + YᵀQ − QᵀY of the right diagonal SO(r)-action is conserved by the flow of (C-neumann), and the Hamiltonian is invariant under that action."""
    z = coupled_point(s)
    psi = lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"] + w["Y"].T @ w["Q"] - w["Q"].T @ w["Y"]
    eta = s.eta
    right = {k: z[k] @ eta for k in ("X", "P", "Y", "Q")}
    return {"d(Psi_X + Psi_Y)/dt": derivative(s, psi, z, coupled_flow(s, H_coupled(FREE_KAPPA))),
            "H right SO(r)-invariant": derivative(s, H_coupled(FREE_KAPPA), z, right)}


def L_big(t, z, nu, sign=1):
    """(so(n,n)): L(ν) = ν[[0, A], [A, 0]] + diag(PXᵀ − XPᵀ, QYᵀ − YQᵀ) + ν⁻¹[[0, XYᵀ], [YXᵀ, 0]]
    (``sign`` = −1: −ν⁻¹ in front of the last term)."""
    X, Y, A = z["X"], z["Y"], t.A
    Z = A - A
    return A_big(t, z, nu) + sign * block([[Z, X @ Y.T], [Y @ X.T, Z]]) * (t.q(1) / nu)


def A_big(t, z, nu):
    """(so(n,n)): A(ν) = L₊(ν) = ν[[0, A], [A, 0]] + diag(PXᵀ − XPᵀ, QYᵀ − YQᵀ)."""
    X, P, Y, Q, A = z["X"], z["P"], z["Y"], z["Q"], t.A
    Z = A - A
    return block([[Z, A], [A, Z]]) * nu + block([[P @ X.T - X @ P.T, Z], [Z, Q @ Y.T - Y @ Q.T]])


def big_lax_residual(s, H, corrected=False):
    """dL/dt − [L, A] along the flow of H for the printed pair (so(n,n)); ``corrected``: dL/dt − [A, L]
    with −ν⁻¹ in front of the last term of L(ν)."""
    z = coupled_point(s)
    nu = s.scalar("nu")
    sign = -1 if corrected else 1
    L = lambda t, w: L_big(t, w, nu, sign)
    flow = coupled_flow(s, H)
    if corrected:
        return derivative(s, L, z, flow) - comm(A_big(s, z, nu), L(s, z))
    return derivative(s, L, z, flow) - comm(L(s, z), A_big(s, z, nu))


_BIG = (r"\dot L(\nu)=[L(\nu),A(\nu)],\ L(\nu)=\begin{pmatrix}0&A\\A&0\end{pmatrix}\nu+"
        r"\begin{pmatrix}PX^T-XP^T&0\\0&QY^T-YQ^T\end{pmatrix}+\begin{pmatrix}0&XY^T\\YX^T&0\end{pmatrix}\nu^{-1},\ "
        r"A(\nu)=L_+(\nu)")

_BIG_ERRATUM = """with the printed L(ν) and A(ν) = L₊(ν) the flow does not imply dL/dt = [L, A].  Write
       J = [[0, A], [A, 0]], M = diag(PXᵀ − XPᵀ, QYᵀ − YQᵀ) and K = [[0, XYᵀ], [YXᵀ, 0]], so that
       L(ν) = νJ + M + ν⁻¹K: on T*V × T*V the flow gives dM/dt = [K, J] and dK/dt = [M, K], so the ν⁰ and ν⁻¹
       parts of the equation need opposite orders of the commutator (already for r = 1; for n = 1, where
       P = Q = 0, it holds).  No single change of a sign or of the order repairs it.
       Corrected: L(ν) = νJ + M − ν⁻¹K and dL/dt = [A(ν), L(ν)] with A(ν) = L₊(ν) (equivalently
       dL/dt = [L(ν), L₋(ν)])."""


BIG_CORRECTION = "(9) §10: −ν⁻¹ in front of the last term of L(ν), and dL/dt = [A(ν), L(ν)]"


@claim("coupled-big-lax-normal", nature="formula", paper=("so(n,n)", "C-eq"), kind="lax", exact_max_n=SYMBOLIC_N_MAX,
       fails_at=lambda n, r: n >= 2,
       place="the big Lax pair (9) §10",
       slips=("A(ν) = L₊(λ) for L₊(ν) in (9) §10",),
       erratum="(9) §10 for κ = 0, along the flow of the Hamiltonian (6) §10 with κ = 0 on T*V × T*V, that is "
               "along (7) §10 with YΠ in place of QΠ (the correction of coupled-neumann-flow): " + _BIG_ERRATUM
               + "  Along (7) §10 as printed, with QΠ, the ν⁰ part fails as well (n ≥ 2), for the printed and the "
               "corrected pair alike: dM/dt gains diag(0, QΠYᵀ − YΠQᵀ), so dM/dt ≠ [K, J], while dK/dt = [M, K] "
               "still holds.  (9) §10 also prints A(ν) = L₊(λ), a slip for L₊(ν): the pair has the one parameter ν, "
               "and the statement here reads L₊(ν).",
       statement=r"\kappa=0:\ " + _BIG)
def coupled_big_lax_normal(s):
    """The r-coupled Neumann system with the normal metric (κ = 0), the flow of (C-neumann) on T*V × T*V, implies the so(n,n) Lax equation (so(n,n)) with the spectral parameter ν."""
    return {"dL(ν)/dt − [L(ν), A(ν)]": big_lax_residual(s, H_coupled(NORMAL))}


@coupled_big_lax_normal.claim.correction(BIG_CORRECTION, changes=2,
                                         exact_max_r={2: 2, 3: 3, 4: 2, 5: 1, 6: 1, 7: 1})
def coupled_big_lax_normal_corrected(s):
    return {"dL(ν)/dt − [L(ν), A(ν)]": big_lax_residual(s, H_coupled(NORMAL), corrected=True)}


@claim("coupled-big-lax-not-euclidean", paper=("so(n,n)", "C-eq"), kind="not", expect="nonzero",
       exact_max_n=SYMBOLIC_N_MAX,
       sizes=admissible(r_min=2, condition="r >= 2 (for r = 1 all the metrics coincide)"),
       statement=r"\kappa=-\tfrac12:\ \dot L(\nu)\neq[A(\nu),L(\nu)]\ \text{along (C-eq)},\ "
                 r"L(\nu)=\nu\begin{pmatrix}0&A\\A&0\end{pmatrix}+\begin{pmatrix}PX^T-XP^T&0\\0&QY^T-YQ^T\end{pmatrix}"
                 r"-\nu^{-1}\begin{pmatrix}0&XY^T\\YX^T&0\end{pmatrix},\ A(\nu)=L_+(\nu)")
def coupled_big_lax_fails_for_the_euclidean_metric(s):
    """As the paper says, the so(n,n) Lax pair does not hold along the r-coupled Neumann system (the flow of (C-neumann)) with the Euclidean metric (κ = −½) when r ≥ 2, even in the corrected form of (so(n,n)) that holds for κ = 0 (see the erratum of coupled-big-lax-normal); the printed form fails for every κ."""
    return {"so(n,n), corrected, kappa = -1/2": big_lax_residual(s, H_coupled(EUCLIDEAN), corrected=True)}


def F_lambda(t, U, V):
    """F_λ(U, V) = Uᵀ(A² − λ²)⁻¹V, with (A² − λ²I_n)⁻¹ = (λI_n − A)⁻¹(−λI_n − A)⁻¹."""
    return U.T @ t.resolvent(t.lam) @ t.resolvent(-t.lam) @ V


def L_dual_coupled(t, z):
    """(LA3*C): the 4r×4r matrix 𝓛(λ)."""
    X, P, Y, Q, A, lam, I = z["X"], z["P"], z["Y"], z["Q"], t.A, t.lam, t.Ir
    F = lambda U, V: F_lambda(t, U, V)
    return block([
        [lam * F(P, X), lam * F(P, P), F(A @ P, Y), -I + F(A @ P, Q)],
        [-lam * F(X, X), -lam * F(X, P), -F(A @ X, Y), -F(A @ X, Q)],
        [F(A @ Q, X), -I + F(A @ Q, P), lam * F(Q, Y), lam * F(Q, Q)],
        [-F(A @ Y, X), -F(A @ Y, P), -lam * F(Y, Y), -lam * F(Y, Q)]])


def A_dual_coupled(t, z, d1, d2):
    """(LA4*C): the 4r×4r matrix 𝓐(λ) with the diagonal blocks d1 (rows 1, 2) and d2 (rows 3, 4)."""
    Lam, Pi = Lambda_Pi_coupled(t, z)
    O, I, lam = _zero_r(t), t.Ir, _scalar_block(t, t.lam)
    return block([[d1, Lam, O, -lam], [I, d1, O, O], [O, -lam, d2, Pi], [O, O, I, d2]])


def dual_coupled_residual(s, H, diagonal):
    z = coupled_point(s)
    d1, d2 = diagonal(s, z)
    return derivative(s, L_dual_coupled, z, coupled_flow(s, H)) - comm(L_dual_coupled(s, z),
                                                                       A_dual_coupled(s, z, d1, d2))


_DUAL_C = (r"\tfrac{d}{dt}\mathcal L(\lambda)=[\mathcal L(\lambda),\mathcal A(\lambda)],\ "
           r"F_\lambda(X,Y)=X^T(A^2-\lambda^2)^{-1}Y,\ \mathcal A(\lambda)=\begin{pmatrix}D_1&\Lambda&0&-\lambda\\"
           r"\mathbf I_r&D_1&0&0\\0&-\lambda&D_2&\Pi\\0&0&\mathbf I_r&D_2\end{pmatrix}")


# (4,1) is proved in 0.6 s (coupled-perturbed-dual-lax: 0.6 s), but the mutation analysis runs every mutant there
# (8 s and 15 s of CPU more in `make mutate`): n <= 3
@claim("coupled-dual-lax", paper=("dual-DC", "LA3*C", "LA4*C", "C-L"), kind="lax", exact_max_n=3,
       statement=r"\kappa=0:\ " + _DUAL_C + r",\ D_1=X^TP,\ D_2=Y^TQ")
def coupled_dual_lax(s):
    """Theorem dual-DC: the r-coupled Neumann system with κ = 0, the flow of (C-neumann) on T*V × T*V, implies the 4r×4r Lax equation (LA3*C) with the printed 𝓛(λ) and 𝓐(λ) of (LA4*C), Λ, Π of (C-L)."""
    diagonal = lambda t, z: (z["X"].T @ z["P"], z["Y"].T @ z["Q"])
    return {"LA3*C": dual_coupled_residual(s, H_coupled(NORMAL), diagonal)}


@claim("coupled-perturbed-big-lax", nature="formula", paper=("so(n,n)", "C-neumann"), kind="lax", exact_max_n=SYMBOLIC_N_MAX,
       fails_at=lambda n, r: n >= 2,
       place="the big Lax pair (9) §10",
       slips=("the references (10) and (11), for (9) §10 and for the matrices of Theorem 10.2, in the paragraph "
              "after Theorem 10.2",),
       erratum="(9) §10 for the perturbed Hamiltonian H_κ = T_κ + tr(XᵀAY) − 2κ tr(XᵀP YᵀQ), every κ, along the "
               "flow of H_κ on T*V × T*V (with the multipliers of both constraint sets; at κ = 0 it is (7) §10 with "
               "YΠ in place of QΠ, the correction of coupled-neumann-flow): " + _BIG_ERRATUM
               + "  That paragraph also refers to the pair as (10) and to the matrices of Theorem 10.2 as (11); these "
               "are the numbers of Theorem 10.2's Lax equation and of the condition (11) §10 defining W_{n,r}: the "
               "pair's label sits in a row of its display that has no number, and that of the matrices in a display "
               "of no number.",
       statement=r"H_\kappa=T_\kappa+\tr(X^TAY)-2\kappa\tr(X^TP\,Y^TQ):\ " + _BIG + r"\ \text{for every }\kappa")
def coupled_perturbed_big_lax(s):
    """For every κ, the flow of the perturbed Hamiltonian H_κ = T_κ + tr(XᵀAY) − 2κ tr(XᵀP YᵀQ) implies the so(n,n) Lax equation (so(n,n))."""
    return {"dL(ν)/dt − [L(ν), A(ν)]": big_lax_residual(s, H_perturbed(FREE_KAPPA))}


@coupled_perturbed_big_lax.claim.correction(BIG_CORRECTION, changes=2,
                                            exact_max_r={2: 2, 3: 3, 4: 2, 5: 1, 6: 1, 7: 1})
def coupled_perturbed_big_lax_corrected(s):
    return {"dL(ν)/dt − [L(ν), A(ν)]": big_lax_residual(s, H_perturbed(FREE_KAPPA), corrected=True)}


@claim("coupled-perturbed-dual-lax", paper=("LA3*C", "LA4*C", "C-neumann"), kind="lax", exact_max_n=3,
       statement=r"H_\kappa:\ " + _DUAL_C + r",\ D_1=(1+2\kappa)X^TP+2\kappa Y^TQ,\ "
                 r"D_2=2\kappa X^TP+(1+2\kappa)Y^TQ\ \text{for every }\kappa")
def coupled_perturbed_dual_lax(s):
    """For every κ, the flow of the perturbed Hamiltonian H_κ implies the Lax equation (LA3*C) with XᵀP and YᵀQ on the diagonal of 𝓐(λ) replaced by (1 + 2κ)XᵀP + 2κYᵀQ and 2κXᵀP + (1 + 2κ)YᵀQ."""
    def diagonal(t, z):
        XP, YQ, k = z["X"].T @ z["P"], z["Y"].T @ z["Q"], t.kappa
        return (1 + 2 * k) * XP + 2 * k * YQ, 2 * k * XP + (1 + 2 * k) * YQ
    return {"LA3*C": dual_coupled_residual(s, H_perturbed(FREE_KAPPA), diagonal)}


# -- for every n, r: along (C-eq) with YΠ, the flow of (C-neumann) ----------------------------------
# The flow of (C-neumann) is (C-eq) with YΠ in place of QΠ (coupled-neumann-flow and its correction, at
# every size); along that matrix expression the dimension-free method proves the rest for all n, r.

def _coupled_primitives(t):
    return {"X": t.X, "P": t.P, "Y": t.Y, "Q": t.Q}


def flow_C_eq_corrected(s, kappa):
    """(C-eq) with YΠ in place of QΠ, as a tangent vector of the scene's T*V × T*V."""
    return flow_C_eq(s, _coupled_primitives(s), kappa, Q_Pi=False)


@claim("coupled-corrected-flow-invariants", paper=("C-eq", "C-L"), kind="id", exact_max_n=4,
       exact_max_r={5: 1, 6: 1, 7: 1},
       statement=r"\text{(C-eq) with }Y\Pi:\ \tfrac{d}{dt}(X^TX)=\tfrac{d}{dt}(X^TP+P^TX)=\tfrac{d}{dt}(Y^TY)="
                 r"\tfrac{d}{dt}(Y^TQ+Q^TY)=0,\ \tfrac{d}{dt}\left(X^TP-P^TX+Y^TQ-Q^TY\right)=0")
def coupled_corrected_flow_invariants(s):
    """For every κ, the r-coupled system (C-eq) with YΠ in place of QΠ (the flow of (C-neumann)) keeps both constraint sets of T*V × T*V and conserves the diagonal SO(r) momentum XᵀP − PᵀX + YᵀQ − QᵀY."""
    flow = flow_C_eq_corrected(s, s.kappa)
    kept = s.d(lambda t: [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X, t.Y.T @ t.Y, t.Y.T @ t.Q + t.Q.T @ t.Y], flow)
    return {"d(X^T X)/dt": kept[0], "d(X^T P + P^T X)/dt": kept[1], "d(Y^T Y)/dt": kept[2],
            "d(Y^T Q + Q^T Y)/dt": kept[3],
            "d(Psi_X + Psi_Y)/dt": s.d(lambda t: t.X.T @ t.P - t.P.T @ t.X + t.Y.T @ t.Q - t.Q.T @ t.Y, flow)}


# (4,1) is proved in 0.6 s, but two of the mutation analysis' mutants there stop at their 30 s budget: n <= 3
@claim("coupled-dual-lax-along-corrected-flow", paper=("dual-DC", "LA3*C", "LA4*C", "C-eq"), kind="lax",
       exact_max_n=3,
       statement=r"\text{(C-eq) with }Y\Pi,\ \kappa=0:\ " + _DUAL_C + r",\ D_1=X^TP,\ D_2=Y^TQ")
def coupled_dual_lax_along_corrected_flow(s):
    """Theorem dual-DC along the matrix equations (C-eq) with κ = 0 and YΠ in place of QΠ (the flow of (C-neumann)): the 4r×4r Lax equation (LA3*C) with the printed 𝓛(λ), 𝓐(λ) of (LA4*C)."""
    z = _coupled_primitives(s)
    A = A_dual_coupled(s, z, s.X.T @ s.P, s.Y.T @ s.Q)
    return {"LA3*C": s.d(lambda t: L_dual_coupled(t, _coupled_primitives(t)), flow_C_eq_corrected(s, s.q(0)))
            - comm(L_dual_coupled(s, z), A)}


@claim("coupled-big-lax-along-corrected-flow", paper=("so(n,n)", "C-eq"), kind="lax", exact_max_n=3,
       exact_max_r={4: 1, 5: 1, 6: 1, 7: 1},
       statement=r"\text{(C-eq) with }Y\Pi,\ \kappa=0:\ \dot L(\nu)=[A(\nu),L(\nu)],\ "
                 r"L(\nu)=\nu\begin{pmatrix}0&A\\A&0\end{pmatrix}+\begin{pmatrix}PX^T-XP^T&0\\0&QY^T-YQ^T\end{pmatrix}"
                 r"-\nu^{-1}\begin{pmatrix}0&XY^T\\YX^T&0\end{pmatrix},\ A(\nu)=L_+(\nu)")
def coupled_big_lax_along_corrected_flow(s):
    """The corrected so(n,n) Lax pair (the erratum of coupled-big-lax-normal: −ν⁻¹ in front of the last term, dL/dt = [A(ν), L(ν)]) holds along the matrix equations (C-eq) with κ = 0 and YΠ in place of QΠ (the flow of (C-neumann))."""
    z, nu = _coupled_primitives(s), s.scalar("nu")
    L = lambda t: L_big(t, _coupled_primitives(t), nu, -1)
    return {"dL(ν)/dt − [L(ν), A(ν)]": s.d(L, flow_C_eq_corrected(s, s.q(0))) - comm(A_big(s, z, nu), L(s))}


# ==== the Neumann system on the complex Stiefel variety W(n, r) ========================================
# Z, Ż are realified (2n × 2r); Zᵀ is the plain transpose (ctranspose), Z̄ the conjugate (s.conj).

def T_complex(t, v):
    """(W-Lag), the kinetic part: ½tr(ŻᵀŻ̄) (real: its real part)."""
    Zd = v["Z"]
    return t.q(1, 2) * re_trace(t, ctranspose(t, Zd) @ t.conj(Zd))


def U_complex(t, q):
    """(W-Lag), the potential: ½tr(ZᵀAZ̄) (real: its real part); L = T − U."""
    Z = q["Z"]
    return t.q(1, 2) * re_trace(t, ctranspose(t, Z) @ realify_real(t, t.A) @ t.conj(Z))


def im_trace(t, M):
    """Im tr M of a realified r×r complex matrix: Re tr(−iM), the sum of the imaginary parts of its diagonal."""
    return re_trace(t, t.realify(_zero_r(t), -t.Ir) @ M)


def W0(t, q):
    """(W0): Z̄ᵀZ − I_r, Hermitian: its r² independent real components."""
    Z = q["Z"]
    return hermitian_entries(ctranspose(t, t.conj(Z)) @ Z - realify_real(t, t.Ir))


def Lambda_complex(t, z):
    """(W-L): Λ = Z̄ᵀAZ − Ż̄ᵀŻ."""
    Z, Zd, A = z["Z"], z["Zdot"], realify_real(t, t.A)
    return ctranspose(t, t.conj(Z)) @ A @ Z - ctranspose(t, t.conj(Zd)) @ Zd


def flow_complex(t, z):
    """(W-eq) as a first-order system: Z̈ = −AZ + ZΛ."""
    A = realify_real(t, t.A)
    return {"Z": z["Zdot"], "Zdot": -(A @ z["Z"]) + z["Z"] @ Lambda_complex(t, z)}


def complex_acceleration(s, z):
    """Z̈ of the Euler–Lagrange equations of (W-Lag) with the constraints (W0) at z."""
    acc, _ = euler_lagrange(s, T_complex, U_complex, W0, {"Z": z["Z"]}, {"Z": z["Zdot"]}, complex_coordinates(s, ["Z"]))
    return acc["Z"]


@claim("complex-neumann-flow", paper=("W0", "W-Lag", "W-eq", "W-L"), kind="id", exact_max_n=2,
       exact_max_r={3: 1, 4: 1},
       statement=r"L=\tfrac12\tr(\dot Z^T\dot{\bar Z})-\tfrac12\tr(Z^TA\bar Z),\ \bar Z^TZ=\mathbf I_r:\quad "
                 r"\ddot Z=-AZ+Z\Lambda,\ \ddot{\bar Z}=-A\bar Z+\bar Z\bar\Lambda,\ "
                 r"\Lambda=\bar Z^TAZ-\dot{\bar Z}^T\dot Z=\bar\Lambda^T")
def complex_neumann_flow(s):
    """The Lagrangian (W-Lag) is real, its Euler–Lagrange equations with the holonomic constraints (W0) on the complex Stiefel variety are the printed (W-eq) with the Hermitian Λ of (W-L), and (W-eq) keeps Z̄ᵀZ = I_r."""
    z = complex_point(s)
    Z, Zd = z["Z"], z["Zdot"]
    acc, printed, A = complex_acceleration(s, z), flow_complex(s, z), realify_real(s, s.A)
    Lam = Lambda_complex(s, z)
    kinetic = ctranspose(s, Zd) @ s.conj(Zd) - ctranspose(s, Z) @ A @ s.conj(Z)
    velocity_constraint = lambda t, w: (ctranspose(t, t.conj(w["Zdot"])) @ w["Z"]
                                        + ctranspose(t, t.conj(w["Z"])) @ w["Zdot"])
    return {
        "Im tr(Z'^T conj Z' - Z^T A conj Z)": im_trace(s, kinetic),
        "Z'' (W-Lag) - (W-eq)": acc - printed["Zdot"],
        "conj Z'' (W-Lag) - (W-eq)": s.conj(acc) - (-(A @ s.conj(Z)) + s.conj(Z) @ s.conj(Lam)),
        "Lambda - conj Lambda^T": Lam - ctranspose(s, s.conj(Lam)),
        "d(conj Z^T Z)/dt": velocity_constraint(s, z),
        "d^2(conj Z^T Z)/dt^2 along (W-eq)": derivative(s, velocity_constraint, z, printed),
    }


def L_dual_complex(t, z, flipped):
    """(LA3*): 𝓛(λ) with R = (λI_n − A)⁻¹ on the diagonal and ``flipped`` off the diagonal."""
    R, F = realify_real(t, t.resolvent(t.lam)), realify_real(t, flipped)
    Z, Zd, T, bar = z["Z"], z["Zdot"], (lambda M: ctranspose(t, M)), t.conj
    I = realify_real(t, t.Ir)
    return block([[-(T(Z) @ R @ bar(Zd)), -(T(Z) @ F @ bar(Z))],
                  [I + T(Zd) @ F @ bar(Zd), T(Zd) @ R @ bar(Z)]])


def A_dual_complex(t, z):
    """(LA3*): 𝓐(λ) = [[0, I_r], [Λ̄ − λI_r, 0]]."""
    I, O = realify_real(t, t.Ir), realify_real(t, _zero_r(t))
    return block([[O, I], [t.conj(Lambda_complex(t, z)) - realify_real(t, _scalar_block(t, t.lam)), O]])


def complex_lax_residual(s, flipped):
    z = complex_point(s)
    L = lambda t, w: L_dual_complex(t, w, flipped(t))
    return derivative(s, L, z, flow_complex(s, z)) - comm(L(s, z), A_dual_complex(s, z))


@claim("complex-neumann-dual-lax", nature="formula", paper=("dual-complex", "LA3*", "W-eq", "W-L"), kind="lax",
       exact_max_n=SYMBOLIC_N_MAX,
       fails_at=lambda n, r: True,
       place="the off-diagonal blocks of 𝓛(λ) in (15) §10, Theorem 10.3",
       erratum="""Theorem 10.3: with (I_n − λA)^{-1} in the off-diagonal blocks of 𝓛(λ), as printed in (15) §10,
       the Neumann system (13) §10 on W_{n,r} does not imply d𝓛/dt = [𝓛, 𝓐].  It does with (λI_n − A)^{-1} in all
       four blocks (the complex form of (2) §8): 𝓛(λ) = [[−ZᵀRŻ̄, −ZᵀRZ̄], [I_r + ŻᵀRŻ̄, ŻᵀRZ̄]],
       R = (λI_n − A)^{-1}.""",
       statement=r"\tfrac{d}{dt}\mathcal L(\lambda)=[\mathcal L(\lambda),\mathcal A(\lambda)],\ "
                 r"\mathcal L=\begin{pmatrix}-Z^T(\lambda\mathbf I_n-A)^{-1}\dot{\bar Z}&-Z^T(\mathbf I_n-\lambda A)^{-1}\bar Z\\"
                 r"\mathbf I_r+\dot Z^T(\mathbf I_n-\lambda A)^{-1}\dot{\bar Z}&"
                 r"\dot Z^T(\lambda\mathbf I_n-A)^{-1}\bar Z\end{pmatrix},\ "
                 r"\mathcal A=\begin{pmatrix}0&\mathbf I_r\\\bar\Lambda-\lambda\mathbf I_r&0\end{pmatrix}")
def complex_neumann_dual_lax(s):
    """Theorem dual-complex: the Neumann system (W-eq) on the complex Stiefel variety implies the 2r×2r Lax equation (LA3*) with the printed 𝓛(λ), whose off-diagonal blocks contain (I_n − λA)⁻¹, and 𝓐(λ)."""
    return {"d𝓛(λ)/dt − [𝓛(λ), 𝓐(λ)]": complex_lax_residual(s, resolvent_flipped)}


@complex_neumann_dual_lax.claim.correction(
    "(15) §10: (λI_n − A)⁻¹ in place of (I_n − λA)⁻¹ in the off-diagonal blocks", exact_max_r={2: 2, 3: 1},
    exact_corank={3: 0, 4: 0, 5: 0, 6: 0, 7: 0}, blocks_of="𝓛(λ) in (15) §10")
def complex_neumann_dual_lax_corrected(s):
    return {"d𝓛(λ)/dt − [𝓛(λ), 𝓐(λ)]": complex_lax_residual(s, lambda t: t.resolvent(t.lam))}


@claim("complex-neumann-momentum-algebra", nature="size", encodes='the conservation of u(n)', paper=("u(1)", "W-eq"), kind="dim", exact_max_n=7,
       sizes=admissible(n_max=5), fails_at=lambda n, r: r != n,
       place="the sentence after (16) §10",
       erratum="""After Theorem 10.3 the symmetries are said to give the conservation of the u(n) and u(1)ⁿ
       momentum maps, ψ₀ = ZᵀŻ̄ − ŻᵀZ̄ the first; ψ₀ is r × r, the momentum of the right U(r)-action that the same
       paragraph names.  Corrected: the u(r) momentum map ψ₀ (claim complex-neumann-momenta proves it conserved).""",
       statement=r"\psi_0=Z^T\dot{\bar Z}-\dot Z^T\bar Z\in u(n):\ \text{size of }\psi_0=n")
def complex_neumann_momentum_algebra(s):
    """The momentum ψ₀ = ZᵀŻ̄ − ŻᵀZ̄ printed after Theorem dual-complex is said to be that of u(n): its size is the
    number of complex columns of Z (n × r complex; realified, two real columns per complex one)."""
    Z = complex_point(s)["Z"]
    # Z realified: two real columns per complex column
    return {"size of ψ₀ = n": Count(Z.shape[1] // 2, s.n, "the size of ψ₀ (r × r, r the number of columns "
                                                        "of Z); printed: n, for ψ₀ ∈ u(n)")}


@complex_neumann_momentum_algebra.claim.correction("u(r) in place of u(n)")
def complex_neumann_momentum_algebra_corrected(s):
    Z = complex_point(s)["Z"]
    return {"size of ψ₀ = r": Count(Z.shape[1] // 2, s.r, "the size of ψ₀ (r × r, r the number of columns "
                                                        "of Z); corrected: r, for ψ₀ ∈ u(r)")}


@claim("complex-neumann-momenta", paper=("W-eq", "u(1)"), kind="pb", exact_max_n=2, exact_max_r={3: 2},
       exact_corank={3: 0, 4: 0, 5: 0, 6: 0, 7: 0},
       statement=r"\tfrac{d}{dt}\psi_0=0,\ \psi_0=Z^T\dot{\bar Z}-\dot Z^T\bar Z;\quad \tfrac{d}{dt}\psi_j=0,\ "
                 r"\psi_j=\sum_{i=1}^r\dot z_i^j\bar z_i^j-z_i^j\dot{\bar z}_i^j\ \text{along (W-eq)}")
def complex_neumann_momenta(s):
    """The momentum ψ₀ = ZᵀŻ̄ − ŻᵀZ̄ of the right U(r)-action and the momenta ψ_j of the left U(1)ⁿ-action (u(1)) (A diagonal) are conserved along (W-eq).  ψ_j = tr(E_j(ŻZ̄ᵀ − ZŻ̄ᵀ)), E_j = EⱼEⱼᵀ = (I − S_j)/2 with S_j the reflection of the j-th coordinate hyperplane: checked for j = 1 at fixed sizes (every j is 1 up to a relabelling of the coordinates) and, dimension-free, for E = (I − S) with every orthogonal symmetry S that commutes with A (every j, and every sum of the ψ_j, at once)."""
    z = complex_point(s)
    flow = flow_complex(s, z)
    psi0 = lambda t, w: ctranspose(t, w["Z"]) @ t.conj(w["Zdot"]) - ctranspose(t, w["Zdot"]) @ t.conj(w["Z"])

    def psi(t, w):
        """Re and Im of ψ_j = tr(E_j M), M = ŻZ̄ᵀ − ZŻ̄ᵀ (Im tr(E M) = −Re tr(iE M))."""
        M = w["Zdot"] @ ctranspose(t, t.conj(w["Z"])) - w["Z"] @ ctranspose(t, t.conj(w["Zdot"]))
        E = realify_real(t, (t.In - twisted.reflection(t)) * t.q(1, 2))
        i = t.realify(t.In - t.In, t.In)
        return [re_trace(t, E @ M), re_trace(t, i @ E @ M)]
    re, im = derivative(s, psi, z, flow)
    return {"d psi_0/dt": derivative(s, psi0, z, flow), "d Re psi_j/dt": re, "d Im psi_j/dt": im}


@claim("complex-neumann-real-data", paper=("W-eq", "W-Lag", "NE_XP"), kind="id",
       statement=r"Z=\bar Z=X,\ \dot Z=\dot{\bar Z}=P:\quad \ddot Z=-AX-XP^TP+XX^TAX\ \text{(NE\_XP)}")
def complex_neumann_real_data(s):
    """At real initial data Z = X ∈ V(n, r), Ż = P, the Euler–Lagrange equations of (W-Lag), (W0) give the real acceleration Ṗ of the Euclidean Neumann system (NE_XP), so (NE_XP) is the subsystem Z = Z̄ of (W-eq)."""
    acc = complex_acceleration(s, real_complex_point(s))
    return {"Z'' - (NE_XP)": acc - realify_real(s, flow_NE(s)["P"])}
