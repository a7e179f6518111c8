# ruff: noqa
"""Helpers shared by claims.py and negatives.py (no claims here)."""
from stiefelsym import block, comm


def theta(t):
    """Theta = Phi + X X^T (Section 6)."""
    return t.Phi + t.X @ t.X.T


def perelomov_L(t, lam):
    """L_neum(lam) = lam Phi + X X^T - lam^2 A (LA2)."""
    return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A


def dual_L(t):
    """L*_neum(lam) (LA3), 2r x 2r, with R = (lam I - A)^{-1}."""
    R = t.resolvent(t.lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def neumann_euclid_flow(s):
    """(NE_XP): Xdot = P, Pdot = -AX - X P^T P + X X^T A X."""
    X, P, A = s.X, s.P, s.A
    return {"X": P, "P": -(A @ X) - X @ P.T @ P + X @ X.T @ A @ X}


def skew_part(M):
    return (M - M.T) / 2


def sym_part(M):
    return (M + M.T) / 2



def manakov_flow(s, op):
    """Xdot = op(Phi) X, Pdot = op(Phi) P (dot_XP2)."""
    M = op(s, s.Phi)
    return {"X": M @ s.X, "P": M @ s.P}
