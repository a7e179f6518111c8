# ruff: noqa: F841, E702, F401
"""Further false statements aimed at the engine's shortcuts (each must FAIL or be undecided, never pass)."""
from stiefelsym import Rank, admissible, claim

from common import hamiltonian, hand_flow

NEG = admissible(n_max=4, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n")


@claim("u2-neg2-rank-everywhere", kind="dim", sizes=[(3, 1), (4, 1), (4, 2)])
def rank_everywhere(s):
    """FALSE: Phi has rank min(2r, 2 floor(n/2)) at EVERY point of T*V (it is 0 at P = 0)."""
    n, r = int(s.n), int(s.r)
    return {"rank Phi everywhere": Rank(s.Phi, min(2 * r, 2 * (n // 2)), generic=False)}


@claim("u2-neg2-tiny", kind="id", sizes=NEG)
def tiny(s):
    """FALSE: dPhi/dt = [XMX^T, A] + 10^-40 Phi (off by a residual far below float64 resolution)."""
    flow = s.dirac_flow(hamiltonian(s.scalar("c")))
    X, A = s.X, s.A
    L = X @ X.T
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - (L @ A @ L @ A - A @ L @ A @ L) - s.q(1, 10**40) * s.Phi}


@claim("u2-neg2-c-squared", kind="id", sizes=NEG)
def c_squared(s):
    """FALSE: Xdot = P - 2c^2 XX^T P (true only at c = 0, 1)."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    return {"dX/dt": flow["X"] - (s.P - 2 * c * c * (s.X @ s.X.T @ s.P))}


@claim("u2-neg2-trM2", kind="id", sizes=NEG)
def trM2(s):
    """FALSE: tr((X^T A X)^2) is conserved."""
    flow = s.dirac_flow(hamiltonian(s.scalar("c")))
    return {"d tr M^2": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X @ t.X.T @ t.A @ t.X), flow)}
