"""s89h3 c9: expect="nonzero" with cancelling words, word-count bounds.
 h3-nz-cancel (expect nonzero; the trace IS zero): tr(GH - HG) ≠ 0 is FALSE -> the right verdict is a failure.
 h3-nz-true (expect nonzero; TRUE): tr(GH - HG + K) ≠ 0 (equals tr K).
 h3-eight (TRUE): tr((G+H)(G-H)(G+K)) - expansion of its 8 words written as separate traces = 0 (8 words: the bound).
 h3-eight-twin (FALSE): the same with the word HHK's sign flipped (tr(HHK) ≠ 0).
 h3-sixteen (TRUE): tr((G+H)(G-H)(G+K)(H+K)) - its 16 words = 0 (beyond the bound: unfused).
 h3-five (TRUE): tr(GHGKH - HGKHG) = 0 (5 factors: rotations, beyond MAX_WORD).
"""
from stiefelsym import claim
SZ = [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)]


def g(s):
    return s.generic("G", "n", "n"), s.generic("H", "n", "n"), s.generic("K", "n", "n")


@claim("h3-nz-cancel", kind="not", sizes=SZ, expect="nonzero")
def nzc(s):
    G, H, K = g(s)
    return {"r": s.tr(G @ H - H @ G)}


@claim("h3-nz-true", kind="not", sizes=SZ, expect="nonzero")
def nzt(s):
    G, H, K = g(s)
    return {"r": s.tr(G @ H - H @ G + K)}


def eight(s, flip):
    G, H, K = g(s)
    t = s.tr
    rhs = (t(G @ G @ G) + t(G @ G @ K) - t(G @ H @ G) - t(G @ H @ K) + t(H @ G @ G) + t(H @ G @ K)
           - t(H @ H @ G) - (-1 if flip else 1) * t(H @ H @ K))
    return {"r": t((G + H) @ (G - H) @ (G + K)) - rhs}


@claim("h3-eight", kind="id", sizes=SZ)
def e8(s):
    return eight(s, False)


@claim("h3-eight-twin", kind="id", sizes=SZ)
def e8t(s):
    return eight(s, True)


@claim("h3-sixteen", kind="id", sizes=SZ)
def e16(s):
    G, H, K = g(s)
    lhs = s.tr((G + H) @ (G - H) @ (G + K) @ (H + K))
    rhs = 0
    import itertools
    for a, b, c, d in itertools.product([0, 1], repeat=4):
        w = [(G, H)[a], (G, H)[b], (G, K)[c], (H, K)[d]]
        sign = -1 if b else 1
        term = s.tr(w[0] @ w[1] @ w[2] @ w[3])
        rhs = rhs + term if sign > 0 else rhs - term
    return {"r": lhs - rhs}


@claim("h3-five", kind="id", sizes=SZ)
def five(s):
    G, H, K = g(s)
    return {"r": s.tr(G @ H @ G @ K @ H - H @ G @ H @ G @ K)}
