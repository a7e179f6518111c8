# ruff: noqa: E702
"""s89h3 c8: words of block matrices and of the n-r blocks.
J = [[G, C], [B, E]] ((n+r)×(n+r)), L = [[X], [F]] ((n+r)×r), M = [[B, E]] (r×(n+r)); D (n-r)×r, Dt r×(n-r) generic.
 h3-blk (TRUE): tr(J L M - L M J) = 0 (cyclicity), one trace.
 h3-blk-twin (FALSE): tr(J L M - J J L M) = 0.
 h3-blk-rot (TRUE): tr(J L M J - M J J L) + tr(M J J L) - tr(L M J J) = 0: tr(JLMJ)=tr(LMJJ) and tr(MJJL) cancels itself.
 h3-nr (TRUE, r<n): tr(D Dt D Dt - Dt D Dt D) = 0 ... ill-typed sum ((n-r)-square minus r-square): must be refused.
 h3-nr2 (TRUE, r<n): tr(D Dt D Dt) - tr(Dt D Dt D) = 0 (two traces).
 h3-nr2-twin (FALSE, r<n): tr(D Dt D Dt) - tr(Dt D Dt D) - tr(D Dt) = 0.
 h3-nr-mix (TRUE): tr(Dt D E + E Dt D - 2 D E Dt ...) -> written tr(Dt D E + E Dt D) - 2 tr(D E Dt) = 0.
"""
from stiefelsym import claim, block
SZ = [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)]
SZ_LT = [(2, 1), (3, 1), (3, 2), (4, 2)]


def mk(s):
    G = s.generic("G", "n", "n"); C = s.generic("C", "n", "r"); B = s.generic("B", "r", "n")
    E = s.generic("E", "r", "r"); F = s.generic("F", "r", "r")
    return block([[G, C], [B, E]]), block([[s.X], [F]]), block([[B, E]])


@claim("h3-blk", kind="id", sizes=SZ)
def blk(s):
    J, L, M = mk(s)
    return {"r": s.tr(J @ L @ M - L @ M @ J)}


@claim("h3-blk-twin", kind="id", sizes=SZ)
def blkt(s):
    J, L, M = mk(s)
    return {"r": s.tr(J @ L @ M - J @ J @ L @ M)}


@claim("h3-blk-rot", kind="id", sizes=SZ)
def blkr(s):
    J, L, M = mk(s)
    return {"r": s.tr(J @ L @ M @ J - L @ M @ J @ J) + s.tr(M @ J @ J @ L) - s.tr(M @ J @ J @ L)}


def nr(s):
    return s.generic("D", "n-r", "r"), s.generic("Dt", "r", "n-r"), s.generic("E", "r", "r")


@claim("h3-nr", kind="id", sizes=SZ_LT)
def nr1(s):
    D, Dt, E = nr(s)
    return {"r": s.tr(D @ Dt @ D @ Dt - Dt @ D @ Dt @ D)}


@claim("h3-nr2", kind="id", sizes=SZ_LT)
def nr2(s):
    D, Dt, E = nr(s)
    return {"r": s.tr(D @ Dt @ D @ Dt) - s.tr(Dt @ D @ Dt @ D)}


@claim("h3-nr2-twin", kind="id", sizes=SZ_LT)
def nr2t(s):
    D, Dt, E = nr(s)
    return {"r": s.tr(D @ Dt @ D @ Dt) - s.tr(Dt @ D @ Dt @ D) - s.tr(D @ Dt)}


@claim("h3-nr-mix", kind="id", sizes=SZ_LT)
def nrm(s):
    D, Dt, E = nr(s)
    return {"r": s.tr(Dt @ D @ E + E @ Dt @ D) - 2 * s.tr(D @ E @ Dt)}
