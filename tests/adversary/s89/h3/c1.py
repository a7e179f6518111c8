# ruff: noqa: E702, F401
"""s89h3: traces of sums of products (the word-expansion path of the exact method).
Notation: X n×r, P n×r, A symmetric n×n, G,H,K generic n×n, B = generic r×n, C = generic n×r.
 h3-rot3 (TRUE): tr(X Xᵀ A) - tr(A X Xᵀ) as one trace: tr(XXᵀA - AXXᵀ) = 0 (cyclicity).
 h3-rect-cancel (TRUE): tr(C B) - tr(B C)  as two traces of rectangular words: 0.
 h3-xxta (FALSE for r<n, TRUE r=n): tr(X Xᵀ A - A) = 0.
 h3-abac (FALSE): tr(G H G K - G G H K) = 0 (not a rotation).
 h3-reflect (FALSE): tr(G H K - K H G) = 0 (reflection, not a rotation).
 h3-sq (TRUE): tr((G+H)(G+H) - GG - GH - HG - HH) = 0 with sums built twice.
 h3-repeat (FALSE): tr(G G H G - G H G H) = 0.
 h3-rep4 (TRUE): tr(GGHG - GHGG) = 0 (rotation).
 h3-res (TRUE): tr(R A R - R R A) = 0, R = resolvent(λ).
 h3-res-false (FALSE): tr(R G R H - R R G H) = 0.
 h3-bc-nz (FALSE as vanishing: nonzero): tr(CB + CB) - 2 tr(BC) ... TRUE = 0.  (check expansion with repeats)
 h3-neg (TRUE): tr(-(G@H) + H@G) = 0.
 h3-neg-false (FALSE): tr(-(G@H) - H@G) = 0.
 h3-mixed (FALSE): tr(C B G - G C B) + tr(G) = 0 (tr G ≠ 0 generic).
 h3-nonzero (expect nonzero, TRUE nonzero): tr(G H K - K H G) ≠ 0 for n ≥ 3; for n = 2 it is 0 (tr(GHK) = tr(KHG) for 2×2? no: false in general) -- see log.
"""
from stiefelsym import admissible, claim

SZ = [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)]


def mats(s):
    G = s.generic("G", "n", "n"); H = s.generic("H", "n", "n"); K = s.generic("K", "n", "n")
    B = s.generic("B", "r", "n"); C = s.generic("C", "n", "r")
    return G, H, K, B, C


@claim("h3-rot3", kind="id", sizes=SZ)
def rot3(s):
    return {"r": s.tr(s.X @ s.X.T @ s.A - s.A @ s.X @ s.X.T)}


@claim("h3-rect-cancel", kind="id", sizes=SZ)
def rect(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(C @ B) - s.tr(B @ C)}


@claim("h3-xxta", kind="id", sizes=SZ)
def xxta(s):
    return {"r": s.tr(s.X @ s.X.T @ s.A - s.A)}


@claim("h3-abac", kind="id", sizes=SZ)
def abac(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(G @ H @ G @ K - G @ G @ H @ K)}


@claim("h3-reflect", kind="id", sizes=SZ)
def reflect(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(G @ H @ K - K @ H @ G)}


@claim("h3-sq", kind="id", sizes=SZ)
def sq(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr((G + H) @ (G + H) - G @ G - G @ H - H @ G - H @ H)}


@claim("h3-repeat", kind="id", sizes=SZ)
def repeat(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(G @ G @ H @ G - G @ H @ G @ H)}


@claim("h3-rep4", kind="id", sizes=SZ)
def rep4(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(G @ G @ H @ G - G @ H @ G @ G)}


@claim("h3-res", kind="id", sizes=SZ)
def res(s):
    R = s.resolvent(s.lam)
    return {"r": s.tr(R @ s.A @ R - R @ R @ s.A)}


@claim("h3-res-false", kind="id", sizes=SZ)
def resf(s):
    G, H, K, B, C = mats(s)
    R = s.resolvent(s.lam)
    return {"r": s.tr(R @ G @ R @ H - R @ R @ G @ H)}


@claim("h3-bc", kind="id", sizes=SZ)
def bc(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(C @ B + C @ B) - 2 * s.tr(B @ C)}


@claim("h3-neg", kind="id", sizes=SZ)
def neg(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(-(G @ H) + H @ G)}


@claim("h3-neg-false", kind="id", sizes=SZ)
def negf(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(-(G @ H) - H @ G)}


@claim("h3-mixed", kind="id", sizes=SZ)
def mixed(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(C @ B @ G - G @ C @ B + G)}


@claim("h3-nonzero", kind="not", sizes=SZ, expect="nonzero")
def nonzero(s):
    G, H, K, B, C = mats(s)
    return {"r": s.tr(G @ H @ K - K @ H @ G)}
