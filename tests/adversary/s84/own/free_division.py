"""Stop 84's own: divisions on the free scene (the classes sweep's M1 of stop 83), and a negative rank.

s84-div-trace:     w/w − 1 with w = tr(PᵀP) (true where P ≠ 0): the free algebra has no inverse of a trace; it says
                   so in words (`undecided`), where it quoted an internal TypeError.
s84-div-trace-f:   w/w − 2 (false): `undecided` under free; refuted by the fixed-size methods.
s84-inv-trace:     1/w − 1/w, the inverse written with the number first (int / scalar): the same words (it quoted
                   "unsupported operand type(s) for /").
s84-inv-size:      (1/tr I_r)·tr I_r − 1 = 0 (true): a division by the size r, which is never 0: proved for all n, r.
s84-inv-size-f:    1/tr I_r − 1 (false at r > 1): refuted by the fixed-size methods; `undecided` under free.
s84-inv-size-nr:   1/(tr I_n − tr I_r) · (tr I_n − tr I_r) − 1 (true where n > r): a division by n − r, 0 at r = n:
                   refused by the free method (no statement for every size follows).
s84-rank-negative: Rank(M, −1): no rank is negative: a false statement, refuted by every fixed-size method (a
                   mutant that drops a term of an expected rank may make it negative: a refutation, not an error).
"""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=3, n_min=2)
SZ_LT = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


def _w(s):
    return s.tr(s.P.T @ s.P)


@claim("s84-div-trace", kind="id", sizes=SZ)
def div_trace(s):
    w = _w(s)
    return {"x": w / w - 1}


@claim("s84-div-trace-f", kind="id", sizes=SZ, expect="fails", erratum="written false on purpose (a twin)")
def div_trace_f(s):
    w = _w(s)
    return {"x": w / w - 2}


@claim("s84-inv-trace", kind="id", sizes=SZ)
def inv_trace(s):
    w = _w(s)
    return {"x": 1 / w - 1 / w}


@claim("s84-inv-size", kind="id", sizes=SZ)
def inv_size(s):
    r = s.tr(s.Ir)
    return {"x": (1 / r) * r - 1}


@claim("s84-inv-size-f", kind="id", sizes=admissible(n_max=3, n_min=2, where=lambda n, r: r > 1), expect="fails", erratum="written false on purpose (a twin)")
def inv_size_f(s):
    r = s.tr(s.Ir)
    return {"x": 1 / r - 1}


@claim("s84-inv-size-nr", kind="id", sizes=SZ_LT)
def inv_size_nr(s):
    d = s.tr(s.In) - s.tr(s.Ir)
    return {"x": (1 / d) * d - 1}


@claim("s84-rank-negative", kind="dim", sizes=SZ, expect="fails",
       erratum="written false on purpose (a twin)")
def rank_negative(s):
    return {"rank": Rank(s.X, -1)}


# a division by a scalar that is identically 0 (a size minus itself, a trace times 0): 1/0 was nan in the free
# algebra (a normal form that is never 0: `undecided`); it is an `error` now, as at every fixed size

@claim("s84-div-zero-size", kind="id", sizes=SZ)
def div_zero_size(s):
    d = s.tr(s.Ir) - s.tr(s.Ir)
    return {"x": (1 / d) * d}


@claim("s84-div-zero-matrix", kind="id", sizes=SZ)
def div_zero_matrix(s):
    d = s.tr(s.Ir) - s.tr(s.Ir)
    return {"x": s.X / d - s.X / d}


@claim("s84-div-zero-trace", kind="id", sizes=SZ)
def div_zero_trace(s):
    d = s.tr(s.P.T @ s.P) * 0
    return {"x": 1 / d - 1 / d}
