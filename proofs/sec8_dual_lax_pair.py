"""§8 The dual Lax pair and geometric interpretation of integrals: the 2r×2r Lax pairs
(LA3), (LA4) of Theorem DUAL for the Neumann flows (N0_XP2) (κ = 0) and (NE_XP) (κ = −½),
the symplectic block structure of 𝓛*_neum(λ) and the SO(r)-invariance of its spectral curve
(2r-integrals)."""
from __future__ import annotations

from stiefelsym import admissible, block, claim, comm

from .sec4_integrability import reflection
from .sec5_neumann import H_neumann_euclidean, H_neumann_normal, power_trace

SECTION = "8"

#: the powers k of tr 𝓛*(λ)^k checked (odd k: they vanish; even k: the spectral curve)
ODD_POWERS = (1, 3)
EVEN_POWERS = (2, 4)


# -- the Lax matrices (LA3), (LA4) --------------------------------------------------------

def L_dual(s):
    """(LA3): 𝓛*_neum(λ) = [[−XᵀRP, −XᵀRX], [I_r + PᵀRP, PᵀRX]], R = (λI_n − A)⁻¹."""
    return L_dual_at(s, s.X, s.P)


def L_dual_at(s, X, P):
    """(LA3) at the point (X, P)."""
    R = s.resolvent(s.lam)
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)],
                  [s.Ir + P.T @ R @ P, P.T @ R @ X]])


def Lambda(s):
    """Theorem DUAL: Λ = XᵀAX − PᵀP."""
    return Lambda_at(s, s.X, s.P)


def Lambda_at(s, X, P):
    """Λ = XᵀAX − PᵀP at the point (X, P)."""
    return X.T @ s.A @ X - P.T @ P


def A_dual_normal(s):
    """(LA4) for (N0_XP2): 𝓐*_neum(λ) = [[XᵀP, I_r], [Λ − λI_r, −PᵀX]]."""
    return A_dual_normal_at(s, s.X, s.P)


def A_dual_normal_at(s, X, P):
    """(LA4) for (N0_XP2) at the point (X, P)."""
    return block([[X.T @ P, s.Ir],
                  [Lambda_at(s, X, P) - s.scalar_matrix(s.lam, s.r, "r"), -(P.T @ X)]])


def A_dual_euclidean(s):
    """(LA4) for (NE_XP): 𝓐*_neum(λ) = [[0, I_r], [Λ − λI_r, 0]]."""
    zero = s.zeros(s.r, s.r, ("r", "r"))
    return block([[zero, s.Ir],
                  [Lambda(s) - s.scalar_matrix(s.lam, s.r, "r"), zero]])


def J(s):
    """The symplectic unit [[0, I_r], [−I_r, 0]] of size 2r."""
    zero = s.zeros(s.r, s.r, ("r", "r"))
    return block([[zero, s.Ir], [-s.Ir, zero]])


def dual_lax_residual(s, H, A_dual):
    """d𝓛*/dt − [𝓛*, 𝓐*] along the Dirac flow of H (the order of (LA3))."""
    flow = s.dirac_flow(H)
    return s.d(L_dual, flow) - comm(L_dual(s), A_dual(s))


# -- Theorem DUAL ---------------------------------------------------------------------------

_L_STATEMENT = (r"\mathcal L^*_{neum}(\lambda)=\begin{pmatrix}-X^TR_\lambda P&-X^TR_\lambda X\\"
                r"\mathbf I_r+P^TR_\lambda P&P^TR_\lambda X\end{pmatrix},\ R_\lambda=(\lambda\mathbf I_n-A)^{-1},\ "
                r"\Lambda=X^TAX-P^TP")


@claim("neumann-dual-lax-normal", paper=("DUAL", "LA3", "LA4", "N0_XP2"), kind="lax",
       sizes=admissible(n_max=5),
       statement=r"\kappa=0:\ \tfrac{d}{dt}\mathcal L^*_{neum}(\lambda)=[\mathcal L^*_{neum}(\lambda),"
                 r"\mathcal A^*_{neum}(\lambda)]\ \text{along (N0\_XP2)},\quad "
                 r"\mathcal A^*_{neum}=\begin{pmatrix}X^TP&\mathbf I_r\\\Lambda-\lambda\mathbf I_r&-P^TX\end{pmatrix},\ "
                 + _L_STATEMENT)
def dual_lax_pair_normal_metric(s):
    """Theorem DUAL for κ = 0: the Dirac flow of H_neum,0 (the Neumann system (N0_XP2)) implies the 2r×2r Lax equation (LA3) with the printed 𝓛*_neum(λ) and the first 𝓐*_neum(λ) of (LA4)."""
    return {"LA3": dual_lax_residual(s, H_neumann_normal, A_dual_normal)}


@claim("neumann-dual-lax-euclidean", paper=("DUAL", "LA3", "LA4", "NE_XP"), kind="lax",
       sizes=admissible(n_max=5),
       statement=r"\kappa=-\tfrac12:\ \tfrac{d}{dt}\mathcal L^*_{neum}(\lambda)=[\mathcal L^*_{neum}(\lambda),"
                 r"\mathcal A^*_{neum}(\lambda)]\ \text{along (NE\_XP)},\quad "
                 r"\mathcal A^*_{neum}=\begin{pmatrix}0&\mathbf I_r\\\Lambda-\lambda\mathbf I_r&0\end{pmatrix},\ "
                 + _L_STATEMENT)
def dual_lax_pair_euclidean_metric(s):
    """Theorem DUAL for κ = −½: the Dirac flow of H_neum,−½ (the Neumann system (NE_XP)) implies the 2r×2r Lax equation (LA3) with the printed 𝓛*_neum(λ) and the second 𝓐*_neum(λ) of (LA4)."""
    return {"LA3": dual_lax_residual(s, H_neumann_euclidean, A_dual_euclidean)}


# -- the spectral curve (2r-integrals) ------------------------------------------------------

@claim("dual-lax-symplectic-structure", paper=("LA4", "2r-integrals"), kind="id",
       sizes=admissible(n_max=5),
       statement=r"(J\mathcal L^*_{neum}(\lambda))^T=J\mathcal L^*_{neum}(\lambda),\ "
                 r"J=\begin{pmatrix}0&\mathbf I_r\\-\mathbf I_r&0\end{pmatrix},\qquad "
                 r"\tr\mathcal L^*_{neum}(\lambda)^k=0\ (k=1,3)")
def dual_lax_matrix_is_hamiltonian(s):
    """𝓛*_neum(λ) lies in the symplectic Lie algebra sp(2r) (J𝓛* is symmetric), so its characteristic polynomial is even in w and the traces of its odd powers vanish (the coefficients at odd powers of w in the spectral curve are zero)."""
    L = L_dual(s)
    JL = J(s) @ L
    checks = {"(J L*)^T - J L*": JL.T - JL}
    for k in ODD_POWERS:
        checks[f"tr L*(lambda)^{k}"] = power_trace(s, L, k)
    return checks


@claim("dual-lax-spectral-invariants", paper=("LA3", "LA4", "2r-integrals"), kind="pb",
       sizes=admissible(n_max=5), exact_max_n=2,
       statement=r"\tfrac{d}{dt}\tr\mathcal L^*_{neum}(\lambda)^k=0\ \text{along (N0\_XP2) and (NE\_XP)},\quad "
                 r"\tfrac{d}{d\epsilon}\tr\mathcal L^*_{neum}(\lambda)^k\big|_{(Xe^{\epsilon\eta},Pe^{\epsilon\eta})}=0,"
                 r"\ \eta\in so(r),\ k=2,4")
def dual_spectral_curve_is_invariant(s):
    """The even traces tr 𝓛*_neum(λ)^k, k = 2, 4 (the coefficients of the spectral curve), are integrals of both Neumann flows (N0_XP2) and (NE_XP) and are invariant under the right SO(r)-action, although 𝓛*_neum(λ) itself is not."""
    normal, euclidean = s.dirac_flow(H_neumann_normal), s.dirac_flow(H_neumann_euclidean)
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    checks = {}
    for k in EVEN_POWERS:
        f = lambda t, k=k: power_trace(t, L_dual(t), k)
        checks[f"d tr L*^{k}/dt along (N0_XP2)"] = s.d(f, normal)
        checks[f"d tr L*^{k}/dt along (NE_XP)"] = s.d(f, euclidean)
        checks[f"d tr L*^{k} along the right so(r)-action"] = s.d(f, right)
    return checks


# -- the Poisson sphere (sp1), (P_q), (P_p) -----------------------------------------------

def H_poisson_sphere(s):
    """The Manakov Hamiltonian ½⟨Φ, 𝔸(Φ)⟩ for B = −A⁻¹, 𝔸(ξ) = A⁻¹ξA⁻¹ ((b_i − b_j)/(a_i − a_j) = 1/(a_i a_j))."""
    return s.killing(s.Phi, s.Ainv @ s.Phi @ s.Ainv) / 2


def flow_poisson_sphere(s):
    """(P_q), (P_p) for r = 1, e = X, p = P: ė = (A⁻¹e, e)A⁻¹p − (A⁻¹e, p)A⁻¹e,
    ṗ = (A⁻¹e, p)A⁻¹p − (A⁻¹p, p)A⁻¹e (the 1×1 products written on the right)."""
    e, p, Ai = s.X, s.P, s.Ainv
    return {"X": Ai @ p @ (e.T @ Ai @ e) - Ai @ e @ (e.T @ Ai @ p),
            "P": Ai @ p @ (e.T @ Ai @ p) - Ai @ e @ (p.T @ Ai @ p)}


@claim("poisson-sphere-flow", paper=("sp1", "P_q", "P_p"), kind="id",
       sizes=admissible(n_max=5, r_max=1, condition="r = 1"), exact_max_n=3,
       statement=r"r=1,\ B=-A^{-1}:\quad \dot e=(A^{-1}e,e)A^{-1}p-(A^{-1}e,p)A^{-1}e,\quad "
                 r"\dot p=(A^{-1}e,p)A^{-1}p-(A^{-1}p,p)A^{-1}e,\quad "
                 r"\tfrac{1}{\langle A^{-1}e,e\rangle}\sum_{i=1}^n a_i\dot e_i^2=2H")
def poisson_sphere_geodesic_flow(s):
    """For r = 1 the Dirac flow of the Manakov Hamiltonian with B = −A⁻¹ is the printed geodesic flow (P_q), (P_p), which is tangent to T*S^{n−1}, and its kinetic energy is that of the printed metric (sp1) (stated multiplied by ⟨A⁻¹e, e⟩)."""
    flow = s.dirac_flow(H_poisson_sphere)
    printed = flow_poisson_sphere(s)
    e = s.X
    kept = s.d(lambda t: [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X], printed)
    edot = printed["X"]
    return {
        "de/dt": flow.Xdot - printed["X"],
        "dp/dt": flow.Pdot - printed["P"],
        "d(e,e)/dt along the printed flow": kept[0],
        "d((e,p)+(p,e))/dt along the printed flow": kept[1],
        "(sp1): sum a_i de_i^2 - 2H (A^{-1}e,e)": s.tr(edot.T @ s.A @ edot)
        - 2 * H_poisson_sphere(s) * s.tr(e.T @ s.Ainv @ e),
    }


# -- the reflections (reflections) ----------------------------------------------------------

@claim("dual-lax-reflections", paper=("DUAL", "reflections", "LA3", "LA4"), kind="id", exact_max_n=3,
       sizes=admissible(n_max=5),
       statement=r"(X,P)\mapsto(S_iX,S_iP):\quad \mathcal L^*_{neum}(\lambda),\ \mathcal A^*_{neum}(\lambda)\ "
                 r"\text{are invariant},\quad i=1,\dots,n")
def reflections_leave_the_dual_pair_invariant(s):
    """The reflections S_i of the coordinate hyperplanes (A diagonal) leave 𝓛*_neum(λ) and both matrices 𝓐*_neum(λ) of (LA4) unchanged, so the dual Lax pair determines the Neumann flows only up to the group ℤ₂ⁿ of Theorem DUAL."""
    X, P = s.X, s.P
    checks = {}
    for i in range(s.n):
        S = reflection(s, i)
        checks[f"S_{i + 1}: L*"] = L_dual_at(s, S @ X, S @ P) - L_dual(s)
        checks[f"S_{i + 1}: A* (N0_XP2)"] = A_dual_normal_at(s, S @ X, S @ P) - A_dual_normal(s)
        checks[f"S_{i + 1}: Lambda (NE_XP)"] = Lambda_at(s, S @ X, S @ P) - Lambda(s)
    return checks
