"""Midpoint-radius matrices in float64: the first, cheapest rung of the ball method.

A matrix is a pair of float64 arrays (mid, rad) with rad >= 0, and stands for every real matrix
X with |X − mid| <= rad entry by entry; every operation returns a pair that contains the exact
result for every choice of its operands in theirs (the inclusion property, as arb's balls have
it).  numpy and BLAS compute in binary64 with rounding to nearest only, so each radius carries an
a-priori bound on the rounding of the midpoint and on the rounding of its own evaluation
(:func:`_inflate`); nothing switches the rounding mode.

The model of floating point (Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed.,
2002, §2.1–2.2, with gradual underflow): u = 2⁻⁵³, η = 2⁻¹⁰⁷⁴ the smallest positive subnormal;
for floats x, y and op in {+, −, ×} (and a fused x·y + z), when no result overflows,

    fl(x op y) = (x op y)(1 + δ) + ε,   |δ| <= u,  |ε| <= η/2,

with ε = 0 for + and − (a sum that falls below the normal range is exact), and also
fl(x ± y) = (x ± y)/(1 + δ'), |δ'| <= u (Higham (2.5)), so |fl(x ± y) − (x ± y)| <= u |fl(x ± y)|.

Dot products (Higham, Thm 3.5 and §3.1; Jeannerod and Rump, SIAM J. Matrix Anal. Appl. 34
(2013) for k u in place of γ_k): BLAS computes each entry of a product of inner dimension k as a
sum of the k products in *some* order, with or without fused multiply-adds (OpenBLAS, MKL and
BLIS do; no mainstream dgemm uses Strassen-type algorithms, for which this fails).  Every term
then passes through at most k roundings and every ε through at most k − 1 more, so

    |fl(A B) − A B| <= γ_k |A||B| + k η,    γ_k = k u / (1 − k u),

and for nonnegative A, B the computed fl(A B) >= (1 − u)^k A B − k η/2 (the lower bound the
radii use: every radius is a sum of nonnegative terms, evaluated in float64 and then inflated).
This is the rounding-to-nearest analysis of midpoint-radius products in Rump, *Fast interval
matrix multiplication*, Numer. Algorithms 61 (2012) 1–34, §4, and Ozaki, Ogita, Oishi and Rump,
*Fast algorithms for floating-point interval matrix multiplication*, J. Comput. Appl. Math. 236
(2012) 1795–1814, written out for this module's few operations with its own constants.

Overflow is never enclosed: an operation whose midpoint or radius is not finite raises
:class:`~stiefelsym.backends.fields.DegenerateError` (the ball method then goes on to arb).  A finite
result of one numpy call had no overflow inside it (an overflowed partial sum stays ±inf or
becomes nan).  Where an operation has no float64 enclosure here (a general inverse), it is done
by arb at 53 bits and its ball converted to an enclosing (mid, rad) pair.

Scalars stay :class:`~stiefelsym.backends.ball.BallNum` (arb balls at 53 bits); term scales follow the
ball backend's rules exactly (float64, not rigorous, see :mod:`stiefelsym.backends.ball`), so the
resolution test compares the same scales at both rungs.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

import flint

from stiefelsym.backends.ball import BallBackend, BallField, BallNum, EnclosureBackend, _upper
from stiefelsym.backends.fields import DegenerateError
from stiefelsym.backends.native import Backend, register_backend

#: the unit roundoff of binary64 (rounding to nearest) and the smallest positive subnormal
U = 2.0**-53
ETA = 2.0**-1074
#: the largest inner dimension (and operation count) the constants below are stated for:
#: (k + 8) u <= 1/2 and every integer multiple of u, η used is exact in float64
K_MAX = 2**40


def _inflate(x: np.ndarray, ops: int, unders: int) -> np.ndarray:
    """A float64 upper bound of z >= 0 from a computed x with x >= (1 − u)^ops z − unders η/2.

    Returns fl(fl(x f) + t) with f = 1 + 2(ops + 2) u and t = (unders + 1) η, both exact floats.
    Proof: fl(x f) >= (1 − u) x f − η/2 and fl(y + t) >= (1 − u)(y + t) (y, t >= 0), so the result
    is at least (1 − u)² f x + (1 − u)(t − η/2) >= (1 − u)^(ops + 2) f z − (1 − u)² f unders η/2
    + (1 − u)(t − η/2).  Since (ops + 2) u <= 1/2, (1 − u)^−(ops+2) <= 1/(1 − (ops + 2) u)
    <= 1 + 2(ops + 2) u = f, and (1 − u) f <= 2, so t − η/2 = unders η covers the last terms:
    the result is >= z.  In place (x is a fresh array of the caller)."""
    if not ops + 2 <= K_MAX or not unders + 1 <= K_MAX:
        raise DegenerateError("a midpoint-radius operation beyond the stated sizes")
    f = 1.0 + 2.0 * (ops + 2) * U
    np.multiply(x, f, out=x)
    np.add(x, (unders + 1) * ETA, out=x)
    return x


def _finite(*arrays: np.ndarray | None) -> None:
    for a in arrays:
        if a is not None and not np.isfinite(a).all():
            raise DegenerateError("a float64 midpoint or radius overflows (arb takes over)")


def _product_radius(P: np.ndarray, Q1: np.ndarray | None, Q2: np.ndarray | None, k: int) -> np.ndarray:
    """The radius of ⟨Am, Ar⟩⟨Bm, Br⟩ about fl(Am Bm) (inner dimension k; a product of entries is
    k = 1), from the computed P = fl(|Am| |Bm|), Q1 = fl(|Am| Br), Q2 = fl(Ar fl(|Bm| + Br)) (None
    where Br, Ar are 0).

    For A' within Ar of Am and B' within Br of Bm,
    |A'B' − fl(Am Bm)| <= |A'B' − Am Bm| + |Am Bm − fl(Am Bm)|
                       <= |Am| Br + Ar(|Bm| + Br) + γ_k |Am||Bm| + k η  =: z.
    With g = (k + 1) u >= γ_k (for k <= 2²⁵: γ_k <= k u (1 + 2 k u) <= g, and g k <= 1), the
    computed x = fl(fl(g P) + fl(Q1 + Q2)) satisfies, by the lower bounds of the module's
    docstring (P >= (1 − u)^k |Am||Bm| − k η/2, Q1 likewise, Q2 >= (1 − u)^(k+1) Ar(|Bm| + Br) −
    k η/2), x >= (1 − u)^(k+3) z − (2k + 1) η: :func:`_inflate` with ops = k + 3, unders = 4k + 2."""
    if not k <= 2**25:
        raise DegenerateError("an inner dimension beyond the stated sizes of the midpoint-radius rung")
    x = np.multiply(P, (k + 1) * U)
    if Q1 is not None and Q2 is not None:
        x += Q1 + Q2
    elif Q1 is not None:
        x += Q1
    elif Q2 is not None:
        x += Q2
    return _inflate(x, k + 3, 4 * k + 2)


class MidRad:
    """A float64 midpoint-radius matrix (``rad`` None: exactly ``mid``), its term scales ``m``
    (as :class:`~stiefelsym.backends.ball.Balls` keeps them) and, for a Cayley matrix, what its inverse
    needs (``beta``, see :func:`_skew_plus_diagonal`).  Never written into once built."""

    __slots__ = ("mid", "rad", "m", "t", "diag", "defer")

    def __init__(self, mid: np.ndarray, rad: np.ndarray | None, m: np.ndarray, defer: tuple | None = None) -> None:
        self.mid, self.rad, self.m, self.defer = mid, rad, m, defer
        self.t: MidRad | None = None
        #: (mid, rad) vectors of a matrix that is diagonal by construction, else None
        self.diag: tuple | None = None

    def shape(self) -> tuple[int, int]:
        return self.defer[-1] if self.defer is not None else self.mid.shape

    def upper_abs(self) -> np.ndarray:
        """An upper bound of |x| for every x in each entry's ball (|mid| + rad, rounded up)."""
        a = np.abs(self.mid)
        if self.rad is None:
            return a
        s = a + self.rad                        # s >= (1 − u)(|mid| + rad): one step up covers it
        # an exact entry (radius 0) keeps |mid| itself: 0 for an exact zero
        return np.where(self.rad == 0, a, np.nextafter(s, math.inf))

    def excludes_zero(self) -> np.ndarray:
        """Where every x in the ball is nonzero: |mid| > rad (a comparison of floats, exact)."""
        if self.rad is None:
            return self.mid != 0
        return np.abs(self.mid) > self.rad

    def ball(self, i: int) -> Any:
        """The entry of flat index i as an arb ball (exact midpoint, radius rounded up)."""
        mid = float(self.mid.flat[i])
        return flint.arb(mid, float(self.rad.flat[i])) if self.rad is not None else flint.arb(mid)


def _pair(b: Any) -> tuple[float, float]:
    """(mid, rad) in float64 enclosing an arb ball: the midpoint rounded, the radius bounding the
    ball's distance from it (arb's upper end, rounded up)."""
    if not b.is_finite():
        raise DegenerateError("a ball that is not finite")
    m = float(b.mid())
    if not math.isfinite(m):
        raise DegenerateError("a ball beyond float64")
    return m, _upper(abs(b - flint.arb(m)))


def _from_balls(balls: list, shape: tuple[int, int], scales: np.ndarray) -> MidRad:
    mid, rad = np.empty(len(balls)), np.empty(len(balls))
    for i, b in enumerate(balls):
        mid[i], rad[i] = _pair(b)
    _finite(rad)
    return MidRad(mid.reshape(shape), rad.reshape(shape), scales)


def _to_arb_mat(a: MidRad) -> Any:
    m, k = a.shape()
    if not (m and k):
        return flint.arb_mat(m, k)
    rad = a.rad.ravel() if a.rad is not None else None
    return flint.arb_mat(m, k, [flint.arb(float(x), float(rad[i])) if rad is not None else flint.arb(float(x))
                                for i, x in enumerate(a.mid.ravel())])


def _skew_plus_diagonal(a: MidRad) -> Any:
    """For an exact square A (rad 0) with A + Aᵀ = 2 diag(d), d > 0: an arb upper bound β of
    ‖A⁻¹‖₂ (xᵀAx = Σ d_i x_i² >= min d ‖x‖², so σ_min(A) >= min d); None otherwise.  A float64
    sum is 0 exactly when it is 0 in ℚ, so the test of the skew part is exact."""
    if a.rad is not None or a.defer is not None:
        return None
    v = a.mid
    k = v.shape[0]
    if k != v.shape[1] or k < DEFERRED_INVERSE_MIN:
        return None
    d = np.diagonal(v)
    dmin = float(np.min(d))
    if not dmin > 0.0:
        return None
    h = v + v.T
    np.fill_diagonal(h, 0.0)
    if np.any(h):
        return None
    return flint.arb(_upper(flint.arb(1) / flint.arb(dmin)))


#: from this many rows on, an inverse of the Cayley chart's kind is deferred: a float64 solve with
#: its residual bound is cheaper than arb's inverse at every size this rung runs at
DEFERRED_INVERSE_MIN = 2

#: the ball method starts with this rung from n = 32 on: a matrix operation here is several numpy
#: calls (tens of microseconds of overhead, whatever the size), one arb call there (about 5 ns a
#: multiply-add).  LA1, CPU: 7.7 against 5.6 ms at (4,2), even at (16,8), 4.3 against 10.9 ms at
#: (24,12), 39 against 470 ms at (200,100); but a claim that sums over a basis of so(16) (tens of
#: thousands of 16 x 16 products) took 7.8 s against arb's 2.8 s at n = 16
MIDRAD_MIN_N = 32


class MidRadField(BallField):
    """The ball field's first rung: the same scalars (arb balls at 53 bits), the same points and
    term scales, with whole matrices as float64 midpoint-radius pairs (:class:`MidRadBackend`)."""

    def __init__(self) -> None:
        super().__init__(53)
        self.name = "midrad53"


class MidRadBackend(EnclosureBackend):
    """Whole matrices as float64 (mid, rad) pairs, every radius a rigorous bound (see the module's
    docstring); scalars and the rare general inverse in arb (:class:`BallBackend`'s rules)."""

    def __init__(self, field: MidRadField) -> None:
        super().__init__(field)
        self._arb = BallBackend(field)

    # -- conversions ------------------------------------------------------------------------------
    def from_array(self, a):
        """Exact float64 inputs (a block of the chart's parameters)."""
        v = np.array(a, dtype=float)
        return MidRad(v, None, np.abs(v))

    def from_consts(self, a):
        if np.max(np.abs(a), initial=0) >= 2**53:
            return self.from_obj(a)
        v = a.astype(float)                     # exact below 2^53
        return MidRad(v, None, np.abs(v))

    def from_obj(self, a):
        m, k = a.shape
        balls, scales = [], np.empty((m, k))
        for idx, x in np.ndenumerate(a):
            if type(x) is not BallNum:
                x = self.field.const(x)
            balls.append(x.b)
            scales[idx] = x.m
        return _from_balls(balls, (m, k), scales)

    def to_obj(self, s):
        s = self._forced(s)
        m, k = s.shape()
        out = np.empty((m, k), dtype=object)
        for i, idx in enumerate(np.ndindex(m, k)):
            out[idx] = BallNum(s.ball(i), float(s.m[idx]))
        return out

    def shape(self, s):
        return s.shape()

    def zeros(self, m, k):
        z = np.zeros((m, k))
        return MidRad(z, None, z)

    def identity(self, m):
        i = np.eye(m)
        out = MidRad(i, None, i)
        out.diag = (np.ones(m), None)
        return out

    def diag(self, xs):
        if not all(type(x) is BallNum for x in xs):
            return Backend.diag(self, xs)
        pairs = [_pair(x.b) for x in xs]
        dm = np.array([p[0] for p in pairs])
        dr = np.array([p[1] for p in pairs])
        dr = dr if np.any(dr) else None
        out = MidRad(np.diag(dm), None if dr is None else np.diag(dr), np.diag([x.m for x in xs]))
        out.diag = (dm, dr)
        return out

    # -- sums ---------------------------------------------------------------------------------------
    def _sum(self, a: MidRad, b: MidRad, sign: float) -> MidRad:
        """a ± b: mid = fl(a.mid ± b.mid), rad >= a.rad + b.rad + u |mid| (the sum's rounding).
        Computed: x = fl(fl(a.rad + b.rad) + fl(u |mid|)) >= (1 − u)² z − η/2 (u |mid| is exact
        unless it falls below the normal range): :func:`_inflate` with ops = 2, unders = 1.
        Of two exact matrices, the rounding error itself: Knuth's TwoSum (Higham, §4.3, Alg. 4.4)
        gives e with mid + e = a.mid ± b.mid exactly (rounding to nearest, no overflow), so the
        radius is |e|, and None where every e is 0 (I + S of the Cayley chart stays exact)."""
        a, b = self._forced(a), self._forced(b)
        bm = b.mid if sign > 0 else -b.mid
        mid = a.mid + bm
        if a.rad is None and b.rad is None:
            bb = mid - a.mid
            err = (a.mid - (mid - bb)) + (bm - bb)
            _finite(mid, err)
            return MidRad(mid, np.abs(err) if np.any(err) else None, a.m + b.m)
        x = np.abs(mid)
        x *= U
        if a.rad is not None:
            x += a.rad
        if b.rad is not None:
            x += b.rad
        # x = 0: both radii 0 and u |mid| = 0, so mid is 0 or below the normal range, where a sum is
        # exact (Higham, §2.1): a ± b = mid exactly, radius 0
        zero = x == 0
        rad = _inflate(x, 2, 1)
        _finite(mid, rad)
        if zero.any():
            rad[zero] = 0.0
        return MidRad(mid, rad, a.m + b.m)

    def add(self, a, b):
        return self._sum(a, b, 1.0)

    def sub(self, a, b):
        return self._sum(a, b, -1.0)

    def neg(self, a):
        a = self._forced(a)
        return MidRad(-a.mid, a.rad, a.m)

    def T(self, a):
        a = self._forced(a)
        if a.t is None:
            a.t = MidRad(a.mid.T, None if a.rad is None else a.rad.T, a.m.T)
            a.t.t = a
            a.t.diag = a.diag
            self._products[(id(a), -1)] = (a, a.t, a.t)      # keeps both alive until release
        return a.t

    # -- products -----------------------------------------------------------------------------------
    def matmul(self, a, b):
        """a b with the radius of :func:`_product_radius`; a product met again (or its transpose)
        is the stored one (the same pair: the computation is deterministic)."""
        out = self._remembered(a, b)
        if out is not None:
            return out
        out = self._deferred_product(a, b)
        if out is None:
            a, b = self._forced(a), self._forced(b)
            (m, k), p = a.shape(), b.shape()[1]
            if k == 0:
                return self.zeros(m, p)
            if a.diag is not None:
                dm, dr = a.diag
                out = _scaled(dm[:, None], None if dr is None else dr[:, None], b.mid, b.rad,
                              np.diagonal(a.m)[:, None] * b.m)
            elif b.diag is not None:
                dm, dr = b.diag
                out = _scaled(dm[None, :], None if dr is None else dr[None, :], a.mid, a.rad,
                              a.m * np.diagonal(b.m)[None, :])
            else:
                out = _product(a, b)
        self._products[(id(a), id(b))] = (a, b, out)
        return out

    def smul(self, a, c):
        a = self._forced(a)
        cm, cr = _pair(c.b)
        out = _scaled(np.float64(cm), np.float64(cr) if cr else None, a.mid, a.rad, a.m * c.m)
        if a.diag is not None:
            dm, dr = a.diag
            d = _scaled(np.float64(cm), np.float64(cr) if cr else None, dm, dr, dm)
            out.diag = (d.mid, d.rad)
        return out

    # -- inverses -----------------------------------------------------------------------------------
    def inv(self, a):
        """The Cayley chart's I + S (exact, skew plus a positive diagonal): deferred, a product with
        it a verified solve (:func:`_cayley_solve`); any other inverse by arb at 53 bits (a rigorous
        enclosure of the inverse of every matrix in the balls), converted to an enclosing pair."""
        a = self._forced(a)
        beta = _skew_plus_diagonal(a)
        if beta is not None:
            k = a.shape()[0]
            return MidRad(None, None, None, ("inv", a, beta, (k, k)))
        try:
            Z = _to_arb_mat(a).inv()
        except ZeroDivisionError as exc:
            raise DegenerateError("a matrix whose balls contain a singular one") from exc
        m, k = a.shape()
        out = _from_balls(Z.entries() if m and k else [], (m, k), np.zeros((m, k)))
        out.m = np.abs(out.mid)
        return out

    def _deferred_product(self, a, b) -> MidRad | None:
        """c A⁻¹ stays deferred; (c A⁻¹) b = c (A⁻¹ b) and A⁻¹ b are solves (as in the arb backend)."""
        if a.defer is None and b.defer is not None and b.defer[0] == "inv":
            _, A, beta, shape = b.defer
            return MidRad(None, None, None, ("mulinv", a, A, beta, (a.shape()[0], shape[1])))
        if b.defer is None and a.defer is not None:
            if a.defer[0] == "inv":
                _, A, beta, _shape = a.defer
                return _cayley_solve(A, beta, b)
            _, c, A, beta, _shape = a.defer
            return self.matmul(c, _cayley_solve(A, beta, b))
        return None

    def _forced(self, a: MidRad) -> MidRad:
        """The values of a deferred inverse (a solve against the identity) or product with one."""
        if a.defer is None:
            return a
        if a.defer[0] == "inv":
            _, A, beta, (k, _k) = a.defer
            done = _cayley_solve(A, beta, self.identity(k))
        else:
            _, c, A, beta, _shape = a.defer
            k = A.shape()[0]
            done = self.matmul(c, _cayley_solve(A, beta, self.identity(k)))
        a.mid, a.rad, a.m, a.defer = done.mid, done.rad, done.m, None
        return a

    # -- reductions ---------------------------------------------------------------------------------
    def trace(self, a):
        a = self._forced(a)
        total = flint.arb(0)
        d = np.diagonal(a.mid)
        r = np.diagonal(a.rad) if a.rad is not None else None
        for i, x in enumerate(d.tolist()):
            total += flint.arb(x, float(r[i])) if r is not None else flint.arb(x)
        return BallNum(total, float(np.trace(a.m)))

    def inner(self, a, b):
        """sum_ij a_ij b_ij: the entrywise products (a product with k = 1) summed by :func:`_total`."""
        a, b = self._forced(a), self._forced(b)
        p = _scaled(a.mid, a.rad, b.mid, b.rad, a.m * b.m)
        return BallNum(_total(p), float(np.sum(a.m * b.m)))

    def is_zero(self, a):
        a = self._forced(a)
        if a.rad is None:
            return not np.any(a.mid)
        return bool(np.all(np.abs(a.mid) <= a.rad))

    def block(self, grid):
        grid = [[self._forced(b) for b in row] for row in grid]
        cat = lambda f: np.concatenate([np.concatenate([f(b) for b in row], axis=1) for row in grid], axis=0)  # noqa: E731
        exact = all(b.rad is None for row in grid for b in row)
        rad = None if exact else cat(lambda b: np.zeros(b.mid.shape) if b.rad is None else b.rad)
        return MidRad(cat(lambda b: b.mid), rad, cat(lambda b: b.m))


def _product(a: MidRad, b: MidRad) -> MidRad:
    """A BLAS product: mid = fl(Am Bm), radius by :func:`_product_radius`; an entry whose every
    term has an exact zero factor (:func:`_structural_zeros`) is exactly 0, radius 0."""
    k = a.mid.shape[1]
    mid = a.mid @ b.mid
    absa, absb = np.abs(a.mid), np.abs(b.mid)
    P = absa @ absb
    Q1 = absa @ b.rad if b.rad is not None else None
    Q2 = a.rad @ (absb + b.rad if b.rad is not None else absb) if a.rad is not None else None
    rad = _product_radius(P, Q1, Q2, k)
    _finite(mid, rad)
    zero = P == 0
    if zero.any():
        _structural_zeros(rad, zero, absa, a.rad, absb, b.rad)
    return MidRad(mid, rad, a.m @ b.m)


def _structural_zeros(rad: np.ndarray, zero: np.ndarray, absa: np.ndarray, ra: np.ndarray | None,
                      absb: np.ndarray, rb: np.ndarray | None) -> None:
    """Radius 0 where every term a_it b_tj has a factor that is exactly 0 (midpoint and radius 0):
    the entry is then 0 for every matrix in the balls, and its floating-point sum of exact zeros is
    ±0 exactly.  The terms that can be nonzero are counted by a float32 product of 0/1 matrices
    (exact below 2^24 terms); only entries whose |Am||Bm| was computed as 0 are candidates."""
    nza = (absa != 0) if ra is None else (absa != 0) | (ra != 0)
    nzb = (absb != 0) if rb is None else (absb != 0) | (rb != 0)
    if absa.shape[1] >= 2**24:
        return
    counts = nza.astype(np.float32) @ nzb.astype(np.float32)
    rad[zero & (counts == 0)] = 0.0


def _scaled(xm: np.ndarray, xr: np.ndarray | None, ym: np.ndarray, yr: np.ndarray | None,
            scales: np.ndarray) -> MidRad:
    """Entrywise (broadcast) products x y, each one rounding: :func:`_product_radius` with k = 1;
    where a factor is exactly 0 (midpoint and radius), the product is exactly ±0, radius 0."""
    mid = xm * ym
    ax, ay = np.abs(xm), np.abs(ym)
    P = np.multiply(ax, ay)
    Q1 = ax * yr if yr is not None else None
    Q2 = xr * (ay + yr if yr is not None else ay) if xr is not None else None
    rad = _product_radius(np.broadcast_to(P, mid.shape).copy() if P.shape != mid.shape else P,
                          Q1, Q2, 1)
    _finite(mid, rad)
    zx = (xm == 0) if xr is None else (xm == 0) & (xr == 0)
    zy = (ym == 0) if yr is None else (ym == 0) & (yr == 0)
    exact = np.broadcast_to(zx | zy, mid.shape)
    if exact.any():
        rad[exact] = 0.0
    return MidRad(mid, rad, scales)


def _total(a: MidRad) -> Any:
    """An arb ball containing the sum of every x in a's balls: s = fl(Σ mid) in any order (numpy's
    pairwise sum) has |s − Σ mid| <= γ_{N−1} Σ |mid| (Higham, §4.2, (4.4): at most N − 1 roundings
    per term, none with an underflow term), and the radii add; the computed sums of the nonnegative
    |mid| and rad are >= (1 − u)^(N−1) times the exact ones.  The radius is evaluated in arb from
    them (rigorous), with γ_{N−1} <= (N − 1)u / (1 − (N − 1)u)."""
    N = a.mid.size
    s = float(np.sum(a.mid))
    sa = float(np.sum(np.abs(a.mid)))
    sr = float(np.sum(a.rad)) if a.rad is not None else 0.0
    if not (math.isfinite(s) and math.isfinite(sa) and math.isfinite(sr)):
        raise DegenerateError("a float64 sum overflows (arb takes over)")
    u = flint.arb(U)
    n1 = max(N - 1, 0)
    lose = (1 - u) ** n1
    gamma = n1 * u / (1 - n1 * u)
    rad = (gamma * flint.arb(sa) + flint.arb(sr)) / lose
    return flint.arb(s, _upper(rad))


def _cayley_solve(A: MidRad, beta: Any, B: MidRad) -> MidRad:
    """An enclosure of A⁻¹B' for every B' in B's balls, A exact with ‖A⁻¹‖₂ <= β.

    Y = LAPACK's float64 solve (any approximation will do); the residual pair R of B − A Y (this
    module's product and difference: it contains B' − A Y for every B'); then
    ‖A⁻¹B' − Y‖_F = ‖A⁻¹(B' − A Y)‖_F <= β ‖B' − A Y‖_F <= β ‖w‖₂ with w = |R.mid| + R.rad, and
    every entry of A⁻¹B' lies within that of Y's.  ‖w‖₂² is computed as one BLAS dot product of
    fl(|R.mid| + R.rad) with itself: each square passes through at most N + 2 roundings (one
    for w, its product, N − 1 additions) and at most N underflow terms η/2 enter, so
    ‖w‖₂² <= (ŝ + N η/2) / (1 − u)^(N+2); the rest in arb."""
    try:
        Y = np.linalg.solve(A.mid, B.mid)
    except np.linalg.LinAlgError as exc:
        raise DegenerateError("a singular float64 approximation of a Cayley matrix") from exc
    _finite(Y)
    Ym = MidRad(Y, None, np.abs(Y))
    AY = _product(A, Ym)
    mid = B.mid - AY.mid
    x = np.abs(mid) * U
    x += AY.rad
    if B.rad is not None:
        x += B.rad
    R = _inflate(x, 2, 1)                      # the radius of B − A Y (see MidRadBackend._sum)
    w = np.abs(mid) + R
    s = float(np.dot(w.ravel(), w.ravel()))
    if not math.isfinite(s):
        raise DegenerateError("a Cayley solve whose residual is not finite")
    N = w.size
    u = flint.arb(U)
    rr = (flint.arb(s) + flint.arb(N) * flint.arb(ETA) / 2) / (1 - u) ** (N + 2)
    radius = _upper(beta * rr.sqrt())
    if not math.isfinite(radius):
        raise DegenerateError("a Cayley solve whose bound is not finite")
    return MidRad(Y, np.full(Y.shape, radius), np.abs(Y) + radius)


register_backend(MidRadField, MidRadBackend)
