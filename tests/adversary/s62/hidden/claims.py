"""s62: nine statements of Fedorov & Jovanovic (Sections 2, 5, 7 and Appendix 1) that the catalog
(`stiefelsym list`, /work/shared/CLAIMS.md) does not state in this form: steps of proofs and remarks.

    timeout 300 .venv/bin/stiefelsym verify --claims tests/adversary/s62/hidden/claims.py \
        --method exact --method modular --method float --method free --method auto --jobs 1 --no-report
"""
from stiefelsym import Count, Rank, claim, comm

from common import (N_GE_2, R_GE_2, R_IS_1, R_IS_2, SMALL, H_neum, H_neum0, action_matrix, dim_so,
                    lax_L, magnetic_equivariance, pr_matrix, stabilizer_element)


# §2 (iso) ------------------------------------------------------------------------------------
@claim("g-iso-inverse", paper=("iso", "P-neutral", "momentum_map"), kind="id", section="2", sizes=SMALL,
       statement=r"X^T\Phi X=\Psi,\quad P=\Phi X-\tfrac12X\Psi,\quad \langle\Phi,(I-XX^T)\zeta(I-XX^T)\rangle=0")
def iso_inverse(s):
    """Section 2, (iso): the restriction of Phi to the fibre T*_X V is an isomorphism onto v = so(n-r)^perp:
    it is inverted by P = Phi X - 1/2 X X^T Phi X (X^T Phi X = Psi) and its image is orthogonal to the
    isotropy algebra so(n-r) = {(I - XX^T) zeta (I - XX^T)}."""
    X, P, Phi, Psi = s.X, s.P, s.Phi, s.Psi
    Q = s.In - X @ X.T
    return {"X^T Phi X - Psi": X.T @ Phi @ X - Psi,
            "P - (Phi X - X Psi / 2)": P - (Phi @ X - X @ Psi / 2),
            "<Phi, Q zeta Q>": s.killing(Phi, Q @ s.xi @ Q)}


# §2 (SO(n-r)-action) corresponds to the adjoint action on v -----------------------------------
@claim("g-isotropy-adjoint", paper=("SO(n-r)-action", "iso"), kind="id", section="2", sizes=SMALL,
       statement=r"\beta=(I-XX^T)\zeta(I-XX^T):\ \beta X=0,\ \delta P=\beta P\in T^*_XV,\ "
                 r"\delta\Phi=[\beta,\Phi],\ \delta\Psi=0")
def isotropy_adjoint(s):
    """Section 2 after (iso): the isotropy SO(n-r) of X acts on the fibre by P -> BP, and under (iso) this is
    the adjoint action on v: for beta in the isotropy algebra the variation (0, beta P) stays in T*_X V,
    moves Phi by [beta, Phi] and leaves Psi fixed."""
    X, P = s.X, s.P
    beta = stabilizer_element(s)
    dP = beta @ P
    return {"beta X": beta @ X,
            "X^T dP + dP^T X": X.T @ dP + dP.T @ X,
            "dPhi - [beta, Phi]": s.d(lambda t: t.Phi, {"P": dP}) - comm(beta, s.Phi),
            "dPsi": s.d(lambda t: t.Psi, {"P": dP})}


# §2 proof of (ddim): the isotropy of a generic (X, P) is SO(n - 2r) -------------------------------
@claim("g-stabilizer-dim", paper=("ddim", "SO(n-r)-action"), kind="dim", section="2", sizes=N_GE_2,
       statement=r"\operatorname{rank}(\xi\mapsto(\xi X,\xi P))=\dim so(n)-\dim so(n-2r)\ (n>2r),\ \dim so(n)\ (n\le2r)")
def stabilizer_dim(s):
    """Proof of the Lemma giving (ddim): SO(n-r)_{P_0} = {I} for n <= 2r and SO(n-2r) for n > 2r; equivalently
    the stabilizer in so(n) of a generic (X, P) has dimension dim so(n - 2r) (0 if n <= 2r)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(action_matrix(s), dim_so(n) - dim_so(n - 2 * r))}


# §5 "Hamiltonians (neumann) are right SO(r)-invariant" ----------------------------------------------
@claim("g-neumann-right-invariant", paper=("neumann", "right_action", "momentum_right_map"), kind="id",
       section="5", sizes=SMALL,
       statement=r"\tfrac{d}{ds}H_{neum,\kappa}(Xe^{s\eta},Pe^{s\eta})|_{s=0}=0")
def neumann_right_invariant(s):
    """Section 5 after (No): the Hamiltonians (neumann) are right SO(r)-invariant for every kappa (so Psi is
    conserved): the derivative of H_neum,kappa along (X eta, P eta) vanishes."""
    return {"dH along (X eta, P eta)": s.d(H_neum, {"X": s.X @ s.eta, "P": s.P @ s.eta})}


# §5 (perelomov): the trace of L and of L^2 -------------------------------------------------------------
@claim("g-perelomov-hamiltonian", paper=("perelomov", "spectral-curve", "LA2", "neumann"), kind="id",
       section="5", sizes=SMALL,
       statement=r"\tr\mathcal L(\lambda)=r-\lambda^2\tr A,\quad \tr\mathcal L(\lambda)^2=r+\lambda^4\tr A^2-4\lambda^2H_{neum,0}")
def perelomov_hamiltonian(s):
    """Section 5, (perelomov): the k = 1 function is trivial and the k = 2 function contains the normal
    Neumann Hamiltonian: tr L = r - lambda^2 tr A, tr L^2 = r + lambda^4 tr A^2 - 4 lambda^2 H_neum,0."""
    L, lam, A = lax_L(s), s.lam, s.A
    r = s.tr(s.Ir)
    return {"tr L": s.tr(L) - (r - lam * lam * s.tr(A)),
            "tr L^2": s.tr(L @ L) - (r + lam ** 4 * s.tr(A @ A) - 4 * lam * lam * H_neum0(s))}


# §7 Psi^{-1}(0) = {X^T P = 0} ---------------------------------------------------------------------------
@claim("g-psi-zero-xtp", paper=("grassmannian", "momentum_right_map"), kind="id", section="7", sizes=SMALL,
       statement=r"\Psi=2X^TP;\ P_0=(I-XX^T)P:\ X^TP_0+P_0^TX=0,\ \Psi(X,P_0)=0,\ \Phi(X,P_0)=\Phi-X\Psi X^T")
def psi_zero_xtp(s):
    """Section 7: (X, P) is in Psi^{-1}(0) iff X^T P = 0, since Psi = 2 X^T P on T*V; projecting P to
    (I - XX^T)P lands in Psi^{-1}(0) and shifts Phi by X Psi X^T."""
    X, P = s.X, s.P
    P0 = P - X @ X.T @ P
    return {"Psi - 2 X^T P": s.Psi - 2 * (X.T @ P),
            "X^T P0 + P0^T X": X.T @ P0 + P0.T @ X,
            "Psi(X, P0)": X.T @ P0 - P0.T @ X,
            "Phi(X, P0) - (Phi - X Psi X^T)": P0 @ X.T - X @ P0.T - (s.Phi - X @ s.Psi @ X.T)}


# App. 1 (OD): {e ^ R^n} = T_e S^{n-1} -----------------------------------------------------------------------
@claim("g-od-rank", paper=("OD", "YM"), kind="dim", section="A1", sizes=R_IS_1,
       statement=r"\operatorname{rank}\pr_{e}=\dim\{e\wedge\mathbb R^n\}=n-1,\quad \dim\{e\wedge\mathbb R^n\}^\perp=\dim so(n-1)")
def od_rank(s):
    """Appendix 1, (OD): {e_n ^ R^n} is identified with T_{e_n}S^{n-1} (dimension n-1) and its complement with
    so(n-1): the projection pr_{e_n}(xi) = xi e (x) e + e (x) e xi has rank n - 1 on so(n)."""
    n = int(s.n)
    return {"rank pr_e": Rank(pr_matrix(s), n - 1),
            "dim so(n) - (n-1) = dim so(n-1)": Count(dim_so(n) - (n - 1), dim_so(n - 1))}


# App. 1: (mag-euk), (mag-nor) are right SO(2)-invariant ---------------------------------------------------
@claim("g-magnetic-equivariant", paper=("mag-euk", "mag-nor", "twisted"), kind="id", section="A1", sizes=R_IS_2,
       statement=r"DV_\epsilon(X,P)[(X\eta,P\eta)]=V_\epsilon(X,P)\eta,\ \eta\in so(2)")
def magnetic_equivariant(s):
    """Appendix 1 after (mag-nor): the equations (mag-euk), (mag-nor) are right SO(2)-invariant: the twisted
    Hamiltonian vector fields V commute with the right action, D V (X eta, P eta) = V eta."""
    return magnetic_equivariance(s, sign=1)


# §5 "for different kappa the flows (No) do not coincide" ------------------------------------------------
@claim("g-neumann-kappa-flows-differ", paper=("No", "Neumann_LA"), kind="not", expect="nonzero", section="5",
       sizes=R_GE_2,
       statement=r"\dot X_{\kappa}\ne\dot X_{0}\ (r\ge2)")
def neumann_kappa_flows_differ(s):
    """Section 5, before (prep): although the derivatives of Phi and XX^T agree, for different kappa the flows
    (No) do not coincide (r >= 2): the X components of the Dirac flows of H_neum,kappa and H_neum,0 differ."""
    return {"Xdot(kappa) - Xdot(0)": s.dirac_flow(H_neum)["X"] - s.dirac_flow(H_neum0)["X"]}
