"""Matrices of the exact backend whose entries each carry their own denominator.

:class:`~stiefelsym.backends.polyfield.PolyMat` keeps every entry over ONE common denominator.  Where the
entries' denominators are many distinct products of atoms (the Dirac multiplier of the metric
chart, Y_ij = C_ij / (m_i + m_j): r(r+1)/2 distinct new factors), the common denominator is a
product of all of them and every numerator is multiplied by all the others: out of reach from
r ≈ 6 on.  A :class:`RatMat` keeps each entry as a reduced rational function (flint numerator,
denominator as atoms with exponents, see :class:`~stiefelsym.backends.polyfield.PolyRing`): a sum of two
entries is over the least common multiple of their two denominators (the larger exponent of each
atom), a product entry sums its terms over the lcm of theirs, and every result entry is reduced
by exact division by its atoms.

The zero test stays exact: an entry is zero iff its numerator is the zero polynomial (its
denominator is a product of nonzero atoms).  A result whose entries share one denominator goes
back to the backend's common-denominator :class:`~stiefelsym.backends.polyfield.PolyMat`.  Only the metric
chart's Lyapunov solve (:meth:`stiefelsym.scene.Scene._lyapunov_native`) makes these matrices;
:class:`~stiefelsym.backends.polyfield.PolyBackend` dispatches here when an operand is one.
"""
from __future__ import annotations

import numpy as np

from stiefelsym.backends import denominators as pf


class RatMat:
    """Numerators (numpy object array of flint polynomials) and, entry by entry, denominators
    (numpy object array of atom tuples); ``o``: the entries as symengine expressions, once made."""

    __slots__ = ("a", "d", "ctx", "o")
    z = False                                  # never flagged as the structural zero

    def __init__(self, a: np.ndarray, d: np.ndarray, ctx) -> None:
        self.a, self.d, self.ctx, self.o = a, d, ctx, None



def _dens(shape, den) -> np.ndarray:
    d = np.empty(shape, dtype=object)
    d.fill(den)
    return d


def fix(be, s: RatMat) -> RatMat:
    """s in the ring's current context (lifted once when the context grew)."""
    return be._fix(s)


def of(be, s) -> RatMat:
    """A PolyMat or RatMat as a RatMat (current context)."""
    if type(s) is RatMat:
        return fix(be, s)
    s = be._fix(s)
    return RatMat(s.a, _dens(s.a.shape, s.den), s.ctx)


def make(be, a: np.ndarray, d: np.ndarray):
    """The result of an operation: a PolyMat when every entry has the same denominator (zero
    entries count as any), a RatMat otherwise."""
    den = None
    for x, e in zip(a.flat, d.flat):
        if x.is_zero():
            continue
        if den is None:
            den = e
        elif den != e:
            den = False
            break
    if den is False:
        return RatMat(a, d, be.ring.ctx)
    if den is None:
        den = pf.NODEN
    R = be.ring
    out = np.empty(a.shape, dtype=object)
    for idx, x in np.ndenumerate(a):
        out[idx] = R.zero if x.is_zero() else x
    a = out
    return be._pm(a, den)


def _reduce_by(R, n, D: tuple, atoms: set):
    """n / D with the given atoms cancelled as far as they divide n (exact divisions)."""
    if not atoms:
        return (n, D)
    return R.cancel(n, D, atoms)


def _sum(R, terms):
    """The sum of rational functions (numerator, atoms) over the lcm of their denominators.

    An atom whose largest exponent is reached by one term only cannot divide the sum when that
    term is reduced (every other term is a multiple of the atom's full power there): only the
    atoms reached by two terms or more are tried (a skipped cancellation leaves an equal fraction,
    not yet reduced; the zero test reads the numerator, which is zero exactly when the sum is).
    A single term is returned as it is (the callers reduce their terms)."""
    terms = [t for t in terms if not t[0].is_zero()]
    if not terms:
        return (R.zero, pf.NODEN)
    if len(terms) == 1:
        return terms[0]
    D = pf.NODEN
    for _, d in terms:
        if d != D:
            D = pf._merge_max(D, d)
    top: dict = {}
    for _, d in terms:
        dd = dict(d)
        for k, e in D:
            if dd.get(k, 0) == e:
                top[k] = top.get(k, 0) + 1
    acc = None
    for n, d in terms:
        x = n if d == D else n * R.den_poly(pf._minus(D, d))
        acc = x if acc is None else acc + x
    if acc.is_zero():
        return (R.zero, pf.NODEN)
    return _reduce_by(R, acc, D, {k for k, c in top.items() if c >= 2})


def _entrywise(be, a, b, sign: int):
    R = be.ring
    A, B = of(be, a), of(be, b)
    m, k = A.a.shape
    na, da = np.empty((m, k), dtype=object), np.empty((m, k), dtype=object)
    for idx, x in np.ndenumerate(A.a):
        y = B.a[idx]
        n, d = _sum(R, [(x, A.d[idx]), (y if sign > 0 else -y, B.d[idx])])
        na[idx], da[idx] = n, d
    return make(be, na, da)


def add(be, a, b):
    return _entrywise(be, a, b, 1)


def sub(be, a, b):
    return _entrywise(be, a, b, -1)


def neg(be, a):
    a = fix(be, a)
    return RatMat(-a.a, a.d, a.ctx)


def T(be, a):
    a = fix(be, a)
    return RatMat(a.a.T.copy(), a.d.T.copy(), a.ctx)


def _cancel(R, n, atoms: tuple):
    """n with the atoms (with exponents) that divide it divided out: (quotient, atoms left)."""
    if not atoms or n.is_zero():
        return n, atoms
    return R.cancel(n, atoms)


def _product(R, x, dx: tuple, y, dy: tuple, memo: dict, kx, ky):
    """(x / dx)(y / dy) with the atoms of dy cancelled from x and those of dx from y (reduced when
    both factors are; divisions of the factors, smaller than the product); ``memo`` keeps each
    factor's cancellation within one product of matrices (kx, ky: the factors' positions)."""
    if dy:
        hit = memo.get((kx, dy))
        if hit is None:
            hit = memo[kx, dy] = _cancel(R, x, dy)
        x, dy = hit
    if dx:
        hit = memo.get((ky, dx))
        if hit is None:
            hit = memo[ky, dx] = _cancel(R, y, dx)
        y, dx = hit
    return (x * y, pf._merge_add(dx, dy))


def matmul(be, a, b):
    R = be.ring
    if getattr(a, "z", False) or getattr(b, "z", False):
        return be.zeros(be.shape(a)[0], be.shape(b)[1])
    A, B = of(be, a), of(be, b)
    (m, k), n = A.a.shape, B.a.shape[1]
    if k == 0:
        return be.zeros(m, n)
    Al, Ad = A.a.tolist(), A.d.tolist()
    Bl, Bd = B.a.T.tolist(), B.d.T.tolist()
    na, da = np.empty((m, n), dtype=object), np.empty((m, n), dtype=object)
    memo: dict = {}
    for i in range(m):
        ai, adi = Al[i], Ad[i]
        for j in range(n):
            bj, bdj = Bl[j], Bd[j]
            terms = [_product(R, x, dx, y, dy, memo, ("a", i, t), ("b", t, j))
                     for t, (x, dx, y, dy) in enumerate(zip(ai, adi, bj, bdj)) if x and y]
            na[i, j], da[i, j] = _sum(R, terms)
    return make(be, na, da)


def smul(be, a, n, d):
    """a times the rational function n / d (atoms d)."""
    R = be.ring
    a = fix(be, a)
    if n.is_zero():
        return be.zeros(*a.a.shape)
    na, da = np.empty(a.a.shape, dtype=object), np.empty(a.a.shape, dtype=object)
    for idx, x in np.ndenumerate(a.a):
        e = a.d[idx]
        na[idx], da[idx] = R.rf_reduce((x * n, pf._merge_add(e, d))) if d else (x * n, e)
    return make(be, na, da)


def trace(be, a):
    R = be.ring
    a = fix(be, a)
    n, d = _sum(R, [(a.a[i, i], a.d[i, i]) for i in range(a.a.shape[0])])
    return be._scalar(n, d)


def inner(be, a, b):
    R = be.ring
    A, B = of(be, a), of(be, b)
    terms = [(x * y, pf._merge_add(dx, dy))
             for x, dx, y, dy in zip(A.a.flat, A.d.flat, B.a.flat, B.d.flat) if x and y]
    n, d = _sum(R, terms)
    return be._scalar(n, d)


def is_zero(be, a) -> bool:
    """Exact: every numerator is the zero polynomial."""
    return not any(a.a.flat)


def to_obj(be, s) -> np.ndarray:
    """The entries as symengine expressions (each reduced over its own denominator)."""
    s = fix(be, s)
    R = be.ring
    out = np.empty(s.a.shape, dtype=object)
    for idx, x in np.ndenumerate(s.a):
        e = s.d[idx]
        out[idx] = R.to_se(R.rf_reduce((x, e)) if e else (x, pf.NODEN))
    return out


def block(be, grid):
    """A block matrix of PolyMats and RatMats (no generic blocks)."""
    grid = [[of(be, b) for b in row] for row in grid]
    a = np.concatenate([np.concatenate([b.a for b in row], axis=1) for row in grid], axis=0)
    d = np.concatenate([np.concatenate([b.d for b in row], axis=1) for row in grid], axis=0)
    return make(be, a, d)


def common(be, s):
    """s over one common denominator (a PolyMat: for the operations without an entrywise form)."""
    s = fix(be, s)
    D = pf.NODEN
    for x, e in zip(s.a.flat, s.d.flat):
        if e and e != D and not x.is_zero():
            D = pf._merge_max(D, e)
    R = be.ring
    out = np.empty(s.a.shape, dtype=object)
    for idx, x in np.ndenumerate(s.a):
        e = s.d[idx]
        out[idx] = R.zero if x.is_zero() else (x if e == D else x * R.den_poly(pf._minus(D, e)))
    return be._pm(out, D)
