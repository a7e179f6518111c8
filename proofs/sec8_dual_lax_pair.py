"""§8 The dual Lax pair and geometric interpretation of integrals: the 2r×2r Lax pairs
(LA3), (LA4) of Theorem DUAL for the Neumann flows (N0_XP2) (κ = 0) and (NE_XP) (κ = −½),
the symplectic block structure of 𝓛*_neum(λ) and the SO(r)-invariance of its spectral curve
(2r-integrals)."""
from __future__ import annotations

from stiefelsym import admissible, block, claim, comm

from .sec5_neumann import H_neumann_euclidean, H_neumann_normal, power_trace

SECTION = "8"

#: the powers k of tr 𝓛*(λ)^k checked (odd k: they vanish; even k: the spectral curve)
ODD_POWERS = (1, 3)
EVEN_POWERS = (2, 4)


# -- the Lax matrices (LA3), (LA4) --------------------------------------------------------

def L_dual(s):
    """(LA3): 𝓛*_neum(λ) = [[−XᵀRP, −XᵀRX], [I_r + PᵀRP, PᵀRX]], R = (λI_n − A)⁻¹."""
    R, X, P = s.resolvent(s.lam), s.X, s.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)],
                  [s.Ir + P.T @ R @ P, P.T @ R @ X]])


def Lambda(s):
    """Theorem DUAL: Λ = XᵀAX − PᵀP."""
    return s.X.T @ s.A @ s.X - s.P.T @ s.P


def A_dual_normal(s):
    """(LA4) for (N0_XP2): 𝓐*_neum(λ) = [[XᵀP, I_r], [Λ − λI_r, −PᵀX]]."""
    X, P = s.X, s.P
    return block([[X.T @ P, s.Ir],
                  [Lambda(s) - s.scalar_matrix(s.lam, s.r, "r"), -(P.T @ X)]])


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
