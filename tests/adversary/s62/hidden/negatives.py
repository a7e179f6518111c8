"""s62: false twins of claims.py, one change each (a factor, an order, a sign, a size range).
Each is false at the sizes marked in README.md and true at a few degenerate sizes (r = 1, n - r <= 1, r = n),
where `proved`/`checked`/`numeric` is the right verdict.

    timeout 300 .venv/bin/stiefelsym verify --claims tests/adversary/s62/hidden/negatives.py \
        --method exact --method modular --method float --method free --method auto --jobs 1 --no-report
"""
from stiefelsym import Rank, claim, comm

from common import (N_GE_2, R_IS_1, R_IS_1_ALL, R_IS_2, SMALL, H_neum, H_neum0, action_matrix, dim_so,
                    lax_L, magnetic_equivariance, pr_matrix, stabilizer_element)


@claim("gn-iso-inverse-factor", paper=("iso",), kind="id", section="2", sizes=SMALL)
def iso_inverse_factor(s):
    """FALSE twin: P = Phi X - X Psi (factor 1/2 dropped); true at r = 1 only (Psi = 0)."""
    X, P, Phi, Psi = s.X, s.P, s.Phi, s.Psi
    Q = s.In - X @ X.T
    return {"X^T Phi X - Psi": X.T @ Phi @ X - Psi,
            "P - (Phi X - X Psi)": P - (Phi @ X - X @ Psi),
            "<Phi, Q zeta Q>": s.killing(Phi, Q @ s.xi @ Q)}


@claim("gn-isotropy-adjoint-order", paper=("SO(n-r)-action",), kind="id", section="2", sizes=SMALL)
def isotropy_adjoint_order(s):
    """FALSE twin: dPhi = [Phi, beta] (commutator reversed); true where n - r <= 1 (beta = 0)."""
    X, P = s.X, s.P
    beta = stabilizer_element(s)
    dP = beta @ P
    return {"beta X": beta @ X,
            "dPhi - [Phi, beta]": s.d(lambda t: t.Phi, {"P": dP}) - comm(s.Phi, beta)}


@claim("gn-stabilizer-dim-so-n-r", paper=("ddim",), kind="dim", section="2", sizes=N_GE_2)
def stabilizer_dim_wrong(s):
    """FALSE twin: the stabilizer of a generic (X, P) is so(n - r) (that of X alone); true where n - r <= 1."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(action_matrix(s), dim_so(n) - dim_so(n - r))}


@claim("gn-neumann-left-invariant", paper=("neumann",), kind="id", section="5", sizes=N_GE_2)
def neumann_left_invariant(s):
    """FALSE twin: H_neum,kappa left SO(n)-invariant (xi X in place of X eta); true at r = n (tr X^T A X = tr A)."""
    return {"dH along (xi X, xi P)": s.d(H_neum, {"X": s.xi @ s.X, "P": s.xi @ s.P})}


@claim("gn-perelomov-hamiltonian-factor", paper=("perelomov",), kind="id", section="5", sizes=SMALL)
def perelomov_hamiltonian_factor(s):
    """FALSE twin: tr L^2 = r + lambda^4 tr A^2 - 2 lambda^2 H_neum,0 (factor 4 -> 2); false everywhere."""
    L, lam, A = lax_L(s), s.lam, s.A
    r = s.tr(s.Ir)
    return {"tr L": s.tr(L) - (r - lam * lam * s.tr(A)),
            "tr L^2": s.tr(L @ L) - (r + lam ** 4 * s.tr(A @ A) - 2 * lam * lam * H_neum0(s))}


@claim("gn-psi-zero-xtp-factor", paper=("grassmannian",), kind="id", section="7", sizes=SMALL)
def psi_zero_xtp_factor(s):
    """FALSE twin: Psi = X^T P (factor 2 dropped); true at r = 1 (Psi = X^T P = 0)."""
    return {"Psi - X^T P": s.Psi - s.X.T @ s.P}


@claim("gn-od-rank-n", paper=("OD",), kind="dim", section="A1", sizes=R_IS_1)
def od_rank_n(s):
    """FALSE twin: pr_e has rank n (the whole R^n in place of T_e S^{n-1})."""
    n = int(s.n)
    return {"rank pr_e": Rank(pr_matrix(s), n)}


@claim("gn-magnetic-equivariant-sign", paper=("mag-euk", "mag-nor"), kind="id", section="A1", sizes=R_IS_2)
def magnetic_equivariant_sign(s):
    """FALSE twin: D V (X eta, P eta) = -V eta (sign)."""
    return magnetic_equivariance(s, sign=-1)


@claim("gn-neumann-kappa-flows-differ-r1", paper=("No",), kind="not", expect="nonzero", section="5",
       sizes=R_IS_1_ALL)
def neumann_kappa_flows_differ_r1(s):
    """FALSE twin (size range): 'the flows (No) differ for different kappa' stated at r = 1, where X P^T X = 0
    and they coincide: must fail."""
    return {"Xdot(kappa) - Xdot(0)": s.dirac_flow(H_neum)["X"] - s.dirac_flow(H_neum0)["X"]}
