# ruff: noqa
"""Ranks of matrices that vanish on T*V but not off it, with and without a kernel certificate that is
nonzero only off T*V.  Honest verdicts: a1, a2, a3 fail (rank 0 on T*V); t1 holds (control)."""
from stiefelsym import Rank, admissible, claim

S = admissible(n_max=4)


@claim("s70-rk-a1", kind="dim", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def a1(s):
    """Generic rank of the 1x1 matrix tr(XᵀX) − r is 1 (false: 0 on V)."""
    c = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    return {"rk": Rank(s.mat([[c]]), 1)}


@claim("s70-rk-a2", kind="dim", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def a2(s):
    """Generic rank of XᵀX − I_r is r (false: 0 on V)."""
    return {"rk": Rank(s.X.T @ s.X - s.Ir, int(s.r))}


@claim("s70-rk-a3", kind="dim", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def a3(s):
    """Rank of [[1, 0], [0, 1]] at every point with a kernel that vanishes on V: rank 1 (false: 2)."""
    c = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    M = s.mat([[1 + 0 * c, 0 * c], [0 * c, 1 + 0 * c]])
    K = s.mat([[c], [0 * c]])
    return {"rk": Rank(M, 1, kernel=K)}


@claim("s70-rk-a4", kind="dim", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def a4(s):
    """M = [[c, 0],[0, 1]] with c = tr(XᵀX) − r and K = [[1],[0]]·(something): rank is 1 on V; claim 2 (false)."""
    c = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    M = s.mat([[c, 0 * c], [0 * c, 1 + 0 * c]])
    return {"rk": Rank(M, 2)}


@claim("s70-rk-a5", kind="dim", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def a5(s):
    """XᵀP + PᵀX has generic rank r (false: 0 on T*V)."""
    return {"rk": Rank(s.X.T @ s.P + s.P.T @ s.X, int(s.r))}


@claim("s70-rk-t1", kind="dim", sizes=S)
def t1(s):
    """XᵀAX has generic rank r (true)."""
    return {"rk": Rank(s.X.T @ s.A @ s.X, int(s.r))}
