# ruff: noqa: F401
"""s89h3 c4: sums inside a trace that a traced function's body also reads; ANY-kind (derivative) scalars in words.
 h3-closure (TRUE): a = tr(GH - HG) = 0, and b = d tr(S P Pᵀ) - tr(S (Ṗ Pᵀ + P Ṗᵀ)) = 0 with S = GH - HG (constant in
   the point), the body of the function reading the same top-level node S.
 h3-closure-twin (FALSE): b with the P Ṗᵀ term dropped (tr(S P Ṗᵀ) ≠ 0 generically; S is not symmetric).
 h3-closure-ham (TRUE): energy conservation dH/dt = 0 for H = ½tr PᵀP + tr(S X Xᵀ) + tr(S) where S = GH - HG + K is a
   top-level sum also traced at the top level (tr S - tr K = 0 is the second check).
 h3-any (TRUE): c = d(½tr PᵀP) along the Neumann flow is a scalar; tr(c·G H - H (c·G)) = 0.
"""
from stiefelsym import admissible, claim

SZ = [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)]


def Hn(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def gens(s):
    return s.generic("G", "n", "n"), s.generic("H", "n", "n"), s.generic("K", "n", "n")


@claim("h3-closure", kind="id", sizes=SZ)
def clo(s):
    G, H, K = gens(s)
    S = G @ H - H @ G
    fl = s.dirac_flow(Hn)
    Pd = fl["P"]
    return {"a": s.tr(S), "b": s.d(lambda t: t.tr(S @ t.P @ t.P.T), fl) - s.tr(S @ (Pd @ s.P.T + s.P @ Pd.T))}


@claim("h3-closure-twin", kind="id", sizes=SZ)
def clot(s):
    G, H, K = gens(s)
    S = G @ H - H @ G
    fl = s.dirac_flow(Hn)
    Pd = fl["P"]
    return {"a": s.tr(S), "b": s.d(lambda t: t.tr(S @ t.P @ t.P.T), fl) - s.tr(S @ (Pd @ s.P.T))}


@claim("h3-closure-ham", kind="id", sizes=SZ)
def cloh(s):
    G, H, K = gens(s)
    S = G @ H - H @ G + K

    def Hs(t):
        return t.tr(t.P.T @ t.P) / 2 + t.tr(S @ t.X @ t.X.T) + t.tr(S)
    return {"e": s.d(Hs, s.dirac_flow(Hs)), "t": s.tr(S) - s.tr(K)}


@claim("h3-any", kind="id", sizes=SZ)
def anyc(s):
    G, H, K = gens(s)
    c = s.d(lambda t: t.tr(t.P.T @ t.P) / 2, s.dirac_flow(Hn))
    return {"r": s.tr((c * G) @ H - H @ (c * G))}
