"""The float64 midpoint-radius rung of the ball method (stiefelsym.backends.midrad) against exact arithmetic.

Soundness: every pair (mid, rad) an operation returns contains the exact result for the extreme
points of its operands' balls (exact rationals), also for entries below float64's normal range;
over the catalog, every enclosure meets arb's at 212 bits at the same exact point.  Negative
controls: the same comparisons with the radii shrunk find exact values outside; a corrupted LA1
fails with a witness certified by this rung."""
from __future__ import annotations

import random
from fractions import Fraction

import flint
import numpy as np
import pytest

from stiefelsym.backends.ball import BallField, Balls, BallNum, working_precision
from stiefelsym.claims import Count, Rank, Size
from stiefelsym.backends.matrix import Mat
from stiefelsym.methods.fixed_size import _flatten, call_claim
from stiefelsym.backends.midrad import MidRad, MidRadBackend, MidRadField
from stiefelsym.backends.native import one_blas_thread, quiet_numpy
from stiefelsym.run.runner import run_one
from stiefelsym.scene import Scene
from stiefelsym.analyses.speed import control_claim

SEED = 0


def _pair(rng: np.random.Generator, shape, exact: bool = False, tiny: bool = False) -> MidRad:
    """Midpoints of mixed signs and sizes (with some below float64's normal range if ``tiny``)."""
    mid = rng.standard_normal(shape) * np.exp2(rng.integers(-30, 30, size=shape))
    if tiny:
        mid[rng.random(shape) < 0.3] *= 2.0**-1040          # products of these underflow
    rad = None if exact else np.abs(rng.standard_normal(shape)) * np.abs(mid) * 2.0**-40
    return MidRad(mid, rad, np.abs(mid))


def _corners(a: MidRad, rng: random.Random) -> list[list[Fraction]]:
    """An exact matrix in a's balls: every entry at an end of its ball or at the midpoint."""
    rows, cols = a.mid.shape
    out = []
    for i in range(rows):
        row = []
        for j in range(cols):
            x = Fraction(float(a.mid[i, j]))
            if a.rad is not None:
                x += rng.choice((-1, 0, 1)) * Fraction(float(a.rad[i, j]))
            row.append(x)
        out.append(row)
    return out


def _outside(c: MidRad, exact: list[list[Fraction]], shrink: float = 1.0) -> list[tuple[int, int]]:
    """The entries whose exact value lies outside mid ± shrink·rad (compared exactly)."""
    bad = []
    for i, row in enumerate(exact):
        for j, x in enumerate(row):
            r = Fraction(float(c.rad[i, j])) if c.rad is not None else Fraction(0)
            if abs(x - Fraction(float(c.mid[i, j]))) > r * Fraction(shrink):
                bad.append((i, j))
    return bad


def _exact_product(A, B):
    return [[sum((A[i][t] * B[t][j] for t in range(len(B))), Fraction(0)) for j in range(len(B[0]))]
            for i in range(len(A))]


def _backend() -> MidRadBackend:
    return MidRadBackend(MidRadField())


OPS = ["product", "product-exact", "product-zero-blocks", "sum", "difference", "sum-exact", "scalar", "diagonal"]


def _apply(op: str, rng: np.random.Generator, prng: random.Random, tiny: bool):
    be = _backend()
    if op == "product-zero-blocks":
        # exact zeros: a's last rows and b's last columns (entries exactly 0, radius 0), and
        # a's first 20 columns against b's first 20 rows (terms with an exact zero factor)
        a, b = _pair(rng, (6, 40), False, tiny), _pair(rng, (40, 5), True, tiny)
        a.mid[4:], a.rad[4:], b.mid[:, 3:] = 0.0, 0.0, 0.0
        a.mid[:, :20], a.rad[:, :20] = 0.0, 0.0
        A, B = _corners(a, prng), _corners(b, prng)
        c = be.matmul(a, b)
        assert not np.any(c.rad[4:]) and not np.any(c.rad[:, 3:])
        return c, _exact_product(A, B)
    if op.startswith("product"):
        a, b = _pair(rng, (6, 40), op == "product-exact", tiny), _pair(rng, (40, 5), op == "product-exact", tiny)
        A, B = _corners(a, prng), _corners(b, prng)
        return be.matmul(a, b), _exact_product(A, B)
    if op in ("sum", "difference", "sum-exact"):
        a, b = _pair(rng, (7, 9), op == "sum-exact", tiny), _pair(rng, (7, 9), op == "sum-exact", tiny)
        A, B = _corners(a, prng), _corners(b, prng)
        sign = -1 if op == "difference" else 1
        c = be.sub(a, b) if sign < 0 else be.add(a, b)
        return c, [[x + sign * y for x, y in zip(ra, rb)] for ra, rb in zip(A, B)]
    if op == "scalar":
        a = _pair(rng, (7, 9), False, tiny)
        lam = flint.arb(1) / 3                          # a ball of radius > 0 around 1/3
        A = _corners(a, prng)
        c = be.smul(a, BallNum(lam, 1.0))
        # the exact 1/3 is inside lam: the enclosure must contain (1/3)·A
        return c, [[x / 3 for x in row] for row in A]
    d = [BallNum(flint.arb(float(x)), abs(float(x))) for x in rng.standard_normal(7)]
    D = be.diag(d)
    a = _pair(rng, (7, 9), False, tiny)
    A = _corners(a, prng)
    return be.matmul(D, a), [[Fraction(float(d[i].b.mid())) * x for x in row] for i, row in enumerate(A)]


@pytest.mark.parametrize("tiny", [False, True], ids=["normal", "underflow"])
@pytest.mark.parametrize("op", OPS)
def test_midpoint_radius_operations_enclose_the_exact_results(op, tiny):
    rng, prng = np.random.default_rng(7), random.Random(7)
    for _ in range(3):
        c, exact = _apply(op, rng, prng, tiny)
        assert not _outside(c, exact), op


@pytest.mark.parametrize("op", ["product-exact", "sum", "difference"])
def test_shrunk_radii_leave_exact_results_outside(op):
    """Negative control: the radii divided by 10⁶ no longer contain the exact results (the bounds
    are sound and the comparison has the power to see an optimistic one)."""
    rng, prng = np.random.default_rng(7), random.Random(7)
    c, exact = _apply(op, rng, prng, False)
    assert not _outside(c, exact)
    assert _outside(c, exact, shrink=1e-6)


@pytest.mark.parametrize("m, r", [(5, 2), (30, 7)])
def test_the_cayley_chart_is_enclosed(m, r):
    """The deferred inverse of I + S (a verified solve) and the products with it contain the exact
    rational values at the same exact parameters (as the arb backend's test does)."""
    from test_ball import _cayley
    from stiefelsym.backends.fields import RationalField

    class Replay(RationalField):
        def param(self, name, rng):
            x = BallField().param(name, rng)
            return flint.fmpq(*Fraction(float(x.b.mid())).as_integer_ratio())
    with working_precision(53):
        out = _cayley(MidRadField(), m, r, random.Random(1))
        exact = _cayley(Replay(), m, r, random.Random(1))
    for B, Q in zip(out, exact):
        assert isinstance(B._nat(), MidRad)
        for i in range(Q._shape()[0]):
            for j in range(Q._shape()[1]):
                b, q = B._view()[i, j], Q._view()[i, j]
                assert isinstance(b, BallNum) and b.b.contains(q)


def test_a_general_inverse_is_enclosed():
    """An inverse that is not of the Cayley kind goes through arb at 53 bits and back to an enclosing
    pair: it contains the exact inverse (exact rational elimination)."""
    rng = np.random.default_rng(3)
    a = MidRad(rng.standard_normal((5, 5)), None, np.ones((5, 5)))
    with working_precision(53):
        z = _backend().inv(a)
    A = [[Fraction(float(x)) for x in row] for row in a.mid]
    n = len(A)
    M = [row + [Fraction(int(i == j)) for j in range(n)] for i, row in enumerate(A)]
    for c in range(n):
        p = next(i for i in range(c, n) if M[i][c] != 0)
        M[c], M[p] = M[p], M[c]
        M[c] = [x / M[c][c] for x in M[c]]
        for i in range(n):
            if i != c and M[i][c] != 0:
                M[i] = [x - M[i][c] * y for x, y in zip(M[i], M[c])]
    assert not _outside(z, [row[n:] for row in M])
    assert _outside(z, [row[n:] for row in M], shrink=1e-6)


# -- over the catalog, against arb at 212 bits ---------------------------------------------------------

def _rng(seed, claim, n, r):
    return random.Random(f"{seed}|{claim.id}|{n}|{r}|float")


def _enclosures(claim, n: int, r: int, field) -> dict[str, list]:
    """Every residual entry of claim at the ball method's point as an arb ball (a midpoint-radius
    entry converted exactly, radius rounded up)."""
    with working_precision(field.prec), one_blas_thread(), quiet_numpy():
        scene = Scene(n, r, field, chart="cayley", rng=_rng(SEED, claim, n, r), realization=claim.realization)
        checks = call_claim(claim.func, scene)
        out = {}
        for name, value in checks.items():
            if isinstance(value, (Rank, Count)):
                continue
            if isinstance(value, Mat) and isinstance(value._n, MidRad):
                s = value._n
                out[name] = [s.ball(i) for i in range(s.mid.size)]
            elif isinstance(value, Mat) and isinstance(value._n, Balls):
                out[name] = value._n.M.entries()
            else:
                out[name] = [x.b if isinstance(x, BallNum) else flint.arb(x) for _, x in _flatten(value, name)]
        return out


def _disjoint(claim, n: int, r: int, shrink: float = 1.0) -> list[str]:
    """The entries where the midpoint-radius enclosure (its radius times ``shrink``) and arb's at
    212 bits are disjoint: both contain the exact value, so a disjoint pair is an unsound radius."""
    mr = _enclosures(claim, n, r, MidRadField())
    ref = _enclosures(claim, n, r, BallField(212))
    bad = []
    with working_precision(212):
        for name, balls in mr.items():
            for i, (b, x) in enumerate(zip(balls, ref[name])):
                shrunk = flint.arb(b.mid(), b.rad() * shrink)
                if not shrunk.overlaps(x):
                    bad.append(f"{name}[{i}]")
    return bad


def _small():
    from test_ball import MODEL
    return MODEL


@pytest.mark.parametrize("cid, size", _small(), ids=[f"{c}[n={s.n},r={s.r}]" for c, s in _small()])
def test_midpoint_radius_enclosures_meet_arb_over_the_catalog(catalog, cid, size):
    assert not _disjoint(catalog.get(cid), size.n, size.r)


@pytest.mark.parametrize("cid, size", [("neumann-lax", Size(4, 2)), ("neumann-flow", Size(6, 3))])
def test_shrunk_midpoint_radius_enclosures_are_caught(catalog, cid, size):
    """Negative control: radii divided by 10⁶ miss arb's enclosure of the exact value somewhere."""
    c = catalog.get(cid)
    assert not _disjoint(c, size.n, size.r)
    assert _disjoint(c, size.n, size.r, shrink=1e-6)


@pytest.mark.parametrize("size", [Size(32, 16), Size(40, 20)], ids=["n=32,r=16", "n=40,r=20"])
def test_a_corrupted_LA1_fails_at_the_midpoint_radius_rung(size):
    res = run_one(control_claim(), size, "ball", seed=SEED)
    assert res.verdict == "fails", res.message
    assert res.witness["field"] == "midrad53" and "excludes 0" in res.certificate


def test_an_overflow_goes_on_to_arb():
    """A midpoint beyond float64 is never enclosed by this rung: it raises, and arb takes over."""
    from stiefelsym.backends.fields import DegenerateError
    be = _backend()
    big = MidRad(np.full((2, 2), 1e300), None, np.full((2, 2), 1e300))
    with pytest.raises(DegenerateError), np.errstate(all="ignore"):
        be.matmul(big, big)
