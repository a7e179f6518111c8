# ruff: noqa: E702
"""s89h3 c6: isolating h3-rnd6-f.  E generic r×r, K = XᵀP (skew on T*V).
 h3-ek (FALSE for r >= 2): tr(E K) = 0  (E generic: tr(E K) = Σ E_ij K_ji ≠ 0 when K ≠ 0).
 h3-ek-sum (FALSE for r >= 2): tr(-(E K) + K K K) - tr(K K K) = 0, i.e. -tr(EK) = 0.
 h3-fk (FALSE for r >= 2): tr(F K) = 0 with the generic named F instead of E.
"""
from stiefelsym import claim
SZ = [(2, 1), (3, 2), (3, 3), (4, 2)]


@claim("h3-ek", kind="id", sizes=SZ)
def ek(s):
    E = s.generic("E", "r", "r")
    return {"r": s.tr(E @ (s.X.T @ s.P))}


@claim("h3-ek-sum", kind="id", sizes=SZ)
def eks(s):
    E = s.generic("E", "r", "r"); K = s.X.T @ s.P
    return {"r": s.tr(-(E @ K) + K @ K @ K) - s.tr(K @ K @ K)}


@claim("h3-fk", kind="id", sizes=SZ)
def fk(s):
    F = s.generic("F", "r", "r")
    return {"r": s.tr(F @ (s.X.T @ s.P))}
