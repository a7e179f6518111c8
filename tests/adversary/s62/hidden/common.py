"""Helpers shared by claims.py and negatives.py (no claims here: a claims file that imports another
claims file would register its claims twice)."""
from stiefelsym import admissible, block, comm
from stiefelsym import twisted
from stiefelsym.bases import matrix_of, so_basis

SMALL = admissible(n_max=4)
N_GE_2 = admissible(n_max=4, n_min=2, condition="n >= 2 (so(1) = 0)")
R_GE_2 = admissible(n_max=4, r_min=2, condition="r >= 2")
R_IS_1 = admissible(n_max=4, n_min=2, r_min=1, r_max=1, condition="r = 1, n >= 2")
R_IS_1_ALL = admissible(n_max=4, r_min=1, r_max=1, condition="r = 1")
R_IS_2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")
N_GE_2_R_BELOW_N = admissible(n_max=4, n_min=2, where=lambda n, r: r < n, condition="n >= 2, r < n")


def H_neum(t):
    """(neumann): H_neum,kappa = 1/2 tr(P^T P) - (1/2 + kappa) tr((X^T P)^2) + 1/2 tr(X^T A X)."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_neum0(t):
    """(neumann) at kappa = 0 (normal metric)."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_neumE(t):
    """(neumann) at kappa = -1/2 (Euclidean metric)."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def stabilizer_element(s):
    """beta = Q zeta Q, Q = I - XX^T: an element of so(n) with beta X = 0 (the so(n-r) of (hat))."""
    Q = s.In - s.X @ s.X.T
    return Q @ s.xi @ Q


def action_matrix(s):
    """The matrix, in the basis E_i ^ E_j of so(n), of xi -> (xi X, xi P)."""
    return matrix_of(s, lambda xi: block([[xi @ s.X, xi @ s.P]]), so_basis(s, "n"))


def dim_so(m):
    return m * (m - 1) // 2 if m > 0 else 0


def pr_e(s, xi):
    """(OD): pr_{e}(xi) = xi e (x) e + e (x) e xi, e = X (r = 1)."""
    e = s.X
    return xi @ e @ e.T + e @ e.T @ xi


def pr_matrix(s):
    return matrix_of(s, lambda xi: pr_e(s, xi), so_basis(s, "n"), "skew")


def lax_L(s):
    """(LA2): L(lambda) = lambda Phi + XX^T - lambda^2 A."""
    lam = s.lam
    return lam * s.Phi + s.X @ s.X.T - lam * lam * s.A


def magnetic_equivariance(s, sign=1):
    """(mag-euk), (mag-nor) are right SO(2)-invariant: D V (X eta, P eta) = V eta for the twisted flows V."""
    eta = s.eta
    tangent = {"X": s.X @ eta, "P": s.P @ eta}
    checks = {}
    for name, H in (("mag-euk", H_neumE), ("mag-nor", H_neum0)):
        V = twisted.flow(s, H)
        for c in ("X", "P"):
            DV = s.d(lambda t, H=H, c=c: twisted.flow(t, H)[c], tangent)
            checks[f"({name}) D V_{c}(X eta, P eta) - {'' if sign == 1 else '-'}V_{c} eta"] = DV - sign * (V[c] @ eta)
    return checks


__all__ = ["comm", "twisted"]
