"""The exact method's flint backend (stiefelsym.backends.polyfield) against the symengine representation:
the same matrices, exact zero tests, cancellation, inverses, growing contexts, the fallback for
entries flint cannot hold, and identical verdicts on claims."""
from __future__ import annotations

import random
import re
from fractions import Fraction

import pytest
import symengine as se

from stiefelsym import admissible, comm

from stiefelsym.backends import native
from stiefelsym.claims import Claim
from stiefelsym.backends.fields import DegenerateError, DualField, SymbolicBudget
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.matrix import Mat, block
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.backends.polyfield import ObjMat, PolyBackend, PolyMat
from stiefelsym.scene import Scene


def fields():
    """The flint-backed field and the symengine one (the representation before the backend)."""
    F = SymbolicField()
    G = SymbolicField()
    G.native = False
    return F, G


def same(x, y, points: int = 3) -> bool:
    """x = y at random rational points (symengine substitution, independent of flint; a scalar the
    backend keeps in flint is compared through its symengine expression)."""
    x, y = (v.to_se() if hasattr(v, "to_se") else v for v in (x, y))
    syms = sorted((x - y).free_symbols, key=str)
    rng = random.Random(7)
    for _ in range(points):
        v = (x - y).subs({t: se.Rational(rng.randint(-10**6, 10**6), rng.randint(1, 10**6)) for t in syms})
        if v != 0:
            return False
    return True


def entries(M):
    v = M._view()
    return [[v[i, j] for j in range(v.shape[1])] for i in range(v.shape[0])]


def rand_mat(F, m, k, syms, rng, dens=()):
    rows = []
    for _ in range(m):
        row = []
        for _ in range(k):
            x = sum((rng.randint(-3, 3) * rng.choice(syms) for _ in range(2)), se.Integer(0))
            x = x + F.const(Fraction(rng.randint(-5, 5), rng.randint(1, 4)))
            if dens and rng.random() < 0.3:
                x = x / rng.choice(dens)
            row.append(x)
        rows.append(row)
    return Mat._rows(rows, F)


def ops(F, syms, rng):
    dens = [syms[0] - syms[1], syms[2], 1 + syms[0] ** 2 + syms[3] ** 2]
    A = rand_mat(F, 3, 3, syms, rng, dens)
    B = rand_mat(F, 3, 2, syms, rng, dens)
    C = rand_mat(F, 2, 3, syms, rng)
    c = syms[4] / (syms[1] + 2)
    M = (A @ B @ C - C.T @ B.T * c + A.inv() @ A.T) * F.const(Fraction(3, 7))
    K = block([[M, A @ B], [C, C @ B]])
    return K, (A @ A.inv()).trace() + M.trace() * c, A._inner(C.T)


def test_backend_is_used_and_agrees_with_symengine():
    for seed in range(2):
        F, G = fields()
        syms = [F.param(f"x{i}") for i in range(5)]
        K1, t1, i1 = ops(F, syms, random.Random(seed))
        K2, t2, i2 = ops(G, syms, random.Random(seed))
        assert isinstance(K1._n, PolyMat) and K2._n is None
        assert all(same(x, y) for r1, r2 in zip(entries(K1), entries(K2)) for x, y in zip(r1, r2))
        assert same(t1, t2)
        assert same(i1, i2)


def test_scalars_of_the_backend_stay_in_flint_and_agree_with_symengine():
    """Traces, pairings and entries are flint rational functions (_RF): sums, products, quotients and
    powers of them stay there, mixed with symengine they give the same value, and the zero test is exact."""
    from stiefelsym.backends.polyfield import _RF
    F, G = fields()
    x = [F.param(f"x{i}") for i in range(4)]

    def scalars(K):
        A = Mat._rows([[x[0], x[1]], [x[2], 1 + x[3]]], K)
        B = Mat._rows([[x[3], se.Integer(1)], [x[0] * x[1], x[2]]], K)
        AB = A @ B
        return AB.trace(), A._inner(B), AB[0, 1], A.inv()[1, 0]
    (t1, i1, e1, v1), (t2, i2, e2, v2) = scalars(F), scalars(G)
    assert all(type(y) is _RF for y in (t1, i1, e1, v1))
    y1 = (t1 * i1 - e1 / (t1 + 1)) ** 2 - Fraction(2, 3) * v1 ** -1
    y2 = (t2 * i2 - e2 / (t2 + 1)) ** 2 - se.Rational(2, 3) * v2 ** -1
    assert type(y1) is _RF and same(y1, y2)
    assert same(x[0] * y1 + 1, y1 * x[0] + 1) and same(x[0] * y1, x[0] * y2)   # symengine on either side
    assert F.is_zero(y1 - y1) and F.is_zero((t1 - t1) * e1) and F.is_zero(y1 - y2)
    assert not F.is_zero(y1 - y2 + x[1])                 # negative control: a nonzero difference
    assert y1 == y2 and y1 != y2 + 1
    assert F.normalize(y1) == y1.to_se() and same(F.normalize(y1), y2)


def test_pairings_of_a_scene_stay_in_flint_and_decide_exactly():
    """<a, b> of the exact scene is a flint scalar (Field.pairing keeps it there, no trip through
    symengine), equal to -1/2 tr(ab) computed as a product and a trace, and a nonzero pairing is nonzero."""
    from stiefelsym.backends.polyfield import _RF
    F = SymbolicField()
    s = Scene(3, 2, F, chart="equivariant")
    a, b = s.generic("a", "n", "n"), s.generic("b", "n", "n")
    kab, kba, kaa = s.killing(a, b), s.killing(b, a), s.killing(a, a)
    assert type(kab) is _RF and type(kaa) is _RF
    by_product = (a @ b).trace() * Fraction(-1, 2)
    assert F.is_zero(kab - kba) and F.is_zero(kab - by_product) and same(kab, by_product.to_se())
    assert not F.is_zero(kaa) and not F.is_zero(kab - kaa) and not F.is_zero(kab + by_product)   # controls
    assert SymbolicField().pairing(se.Integer(3)) == 3           # anything else is normalized as before


def test_a_symbolic_solve_takes_flint_scalars_on_either_side():
    """SymbolicField.solve with flint scalars (_RF: traces, pairings) in the matrix and the right-hand side
    gives scalars, the solution of the system (before, symengine took an _RF for an empty matrix and every
    entry of the solution was a 0x0 matrix: the exact metric Dirac flow at (3,1) with the reflection S)."""
    from stiefelsym.backends.polyfield import _RF
    F, G = fields()
    x = [F.param(f"x{i}") for i in range(4)]

    def system(K):
        A = Mat._rows([[x[0], x[1]], [x[2], 1 + x[3]]], K)
        t, e = (A @ A).trace(), (A @ A)[0, 1]
        return [[se.Integer(0), t], [-t, se.Integer(0)]], [[e], [t * e + 1]]
    (M1, B1), (M2, B2) = system(F), system(G)
    assert type(B1[0][0]) is _RF and type(M1[0][1]) is _RF
    Y1 = F.solve(M1, B1)
    for i in range(2):      # M Y = B, and the same Y as the system written in symengine
        assert not isinstance(Y1[i][0], se.DenseMatrix), Y1
        assert F.is_zero(sum((M1[i][k] * Y1[k][0] for k in range(2)), se.Integer(0)) - B1[i][0])
        assert same(Y1[i][0], G.solve(M2, B2)[i][0])
    assert not F.is_zero(Y1[0][0] - Y1[1][0])          # negative control: a nonzero difference


def test_the_text_of_a_rational_function_does_not_depend_on_the_order_of_the_ring_variables():
    """The exact residual's text (PolyRing.text): terms in degree-lexicographic order of the variables'
    names, each denominator factor with a positive leading coefficient, the factors sorted; the same text
    whatever order the ring met its variables in (before: flint's order of first use, which depends on
    what the process computed before, e.g. the mutants run before one in a mutation analysis)."""
    texts = []
    for names in (("b_1", "a_10", "a_2"), ("a_2", "a_10", "b_1"), ("a_10", "b_1", "a_2")):
        F = SymbolicField()
        R = F.poly_ring()
        v = {name: F.param(name) for name in names}
        a, b, c = v["b_1"], v["a_10"], v["a_2"]
        x = (a ** 2 * b - 3 * c + b * c ** 2 - 1) / ((c - a) * (a + 1) ** 2)
        y = -(a ** 2 * b - 3 * c + b * c ** 2 - 1) / ((a - c) * (a + 1) ** 2)       # the same function
        z = (a ** 2 * b - 3 * c + b * c ** 2 + 1) / ((c - a) * (a + 1) ** 2)       # another one
        texts.append((R.text(R.from_se(x)), R.text(R.from_se(y)), R.text(R.from_se(z)), R.poly_text(
            R.from_se(se.expand(b * c ** 2 + a * b - c ** 3))[0])))
    assert len(set(texts)) == 1, texts
    # the parameters' own names (an older python-flint or symengine prints them with a leading underscore)
    tx, ty, tz, tp = (re.sub(r"(?<![\w])_(?=[ab]_)", "", t) for t in texts[0])
    assert tx == ty == "(a_2**2*a_10 + a_10*b_1**2 - 3*a_2 - 1)/((a_2 - b_1)*(b_1 + 1)**2)", tx
    assert tz != tx and tp == "-a_2**3 + a_2**2*a_10 + a_10*b_1", tp      # negative control; natural order


def test_native_backend_hook():
    F, G = fields()
    assert isinstance(native.backend(F), PolyBackend)
    assert native.backend(G) is None
    assert isinstance(native.backend(DualField(F)), native.DualBackend)


def test_cayley_point_cancels_to_the_identity():
    """X^T X = I in the Cayley chart: the common denominator det(I + S)^2 cancels completely."""
    for r in (1, 2, 3):
        s = Scene(3, r, SymbolicField(), chart="cayley")
        XtX = s.X.T @ s.X
        assert isinstance(XtX._n, PolyMat) and XtX._n.den == ()
        assert (XtX - s.Ir).is_zero()
        assert not (XtX - s.Ir * 2).is_zero()


def test_inverse_and_singular_and_budget():
    F = SymbolicField()
    x, y, z = (F.param(n) for n in "xyz")
    M = Mat._rows([[x, y, 1], [z, x * y, y], [1, z, x / y]], F)
    assert (M @ M.inv() - Mat.identity(3, F)).is_zero()
    S = Mat._rows([[x, y], [2 * x, 2 * y]], F)
    with pytest.raises(DegenerateError):
        S.inv()
    # a dense 4x4 is one diagonal pivot and a 3x3 core (within budget by its size); a dense 5x5 whose entries have
    # degree <= 1 by its shape (up to 6x6: I + S of the Cayley chart at r = n); beyond those rules, up to 6x6, by
    # the work of its elimination (SOLVE_TERM_PRODUCTS: a dense 5x5 in two parameters takes about 10⁴ term
    # products); a 7x7 beyond those rules is refused for its size
    B4 = Mat._rows([[x if i == j else y + i * j for j in range(4)] for i in range(4)], F)
    assert (B4 @ B4.inv() - Mat.identity(4, F)).is_zero()
    L5 = Mat._rows([[x if i == j else y + i * j for j in range(5)] for i in range(5)], F)
    assert (L5 @ L5.inv() - Mat.identity(5, F)).is_zero()
    B5 = Mat._rows([[x * y if i == j else y + i * j for j in range(5)] for i in range(5)], F)
    assert (B5 @ B5.inv() - Mat.identity(5, F)).is_zero()
    L7 = Mat._rows([[x if i == j else y + i * j for j in range(7)] for i in range(7)], F)
    with pytest.raises(SymbolicBudget, match=r"^a symbolic 7x7 linear solve$"):
        L7.inv()
    N4 = Mat._rows([[1 if i == j else (x if j > i else 0) for j in range(4)] for i in range(4)], F)
    assert (N4 @ N4.inv() - Mat.identity(4, F)).is_zero()


def test_budget_counts_the_work_of_a_symbolic_inverse():
    """Beyond the rules of size and shape a symbolic inverse is taken while its term products stay within
    SOLVE_TERM_PRODUCTS: I + S + kkᵀ (5 x 5, S skew, k a vector; the reduced Cayley chart at (6, 5)) is inverted; a
    6 x 6 of products of two parameters is refused by its size, at the same step wherever it runs; a singular
    5 x 5 of degree 2 is singular, neither inverted nor refused for its size."""
    F = SymbolicField()
    m = 5
    S = {(i, j): F.param(f"s{i}{j}") for i in range(m) for j in range(i + 1, m)}
    k = [F.param(f"k{i}") for i in range(m)]
    M = Mat._rows([[int(i == j) + (S[i, j] if i < j else -S[j, i] if j < i else 0) + k[i] * k[j] for j in range(m)]
                   for i in range(m)], F)
    assert (M @ M.inv() - Mat.identity(m, F)).is_zero()
    G = Mat._rows([[F.param(f"g{i}{j}") * F.param(f"h{i}{j}") + int(i == j) for j in range(6)] for i in range(6)], F)
    with pytest.raises(SymbolicBudget, match=r"^a symbolic 6x6 linear solve$"):
        G.inv()
    # the last row the sum of the others: det = 0 as a polynomial, every pivot of the elimination nonzero but the last
    rows = [[F.param(f"u{i}{j}") * F.param(f"v{i}{j}") + int(i == j) for j in range(m)] for i in range(m - 1)]
    rows.append([sum((row[j] for row in rows), se.Integer(0)) for j in range(m)])
    with pytest.raises(DegenerateError):
        Mat._rows(rows, F).inv()


def test_budget_admits_a_small_core():
    """A 7x7 arrowhead (nonzeros off the diagonal only in 3 rows and their columns) is a 3x3 symbolic
    solve after diagonal pivots: inverted exactly; with a 4-row border it is refused."""
    F = SymbolicField()

    def arrow(m, k):
        ps = [F.param(f"p{i}") for i in range(m)]
        qs = {(i, j): F.param(f"q{i}_{j}") for i in range(k) for j in range(k, m)}
        return Mat._rows([[ps[i] if i == j else qs.get((min(i, j), max(i, j)), 0) if min(i, j) < k else 0
                           for j in range(m)] for i in range(m)], F)
    A = arrow(7, 3)
    assert (A @ A.inv() - Mat.identity(7, F)).is_zero()
    with pytest.raises(SymbolicBudget):
        arrow(8, 4).inv()


def test_zero_test_is_exact():
    """A polynomial that vanishes at many integer points is not zero; a sum that cancels is."""
    F = SymbolicField()
    x, y = F.param("x"), F.param("y")
    p = se.Integer(1)
    for i in range(40):
        p = p * (x - i)
    assert not F.is_zero(p)
    assert not Mat._rows([[p, 0]], F).is_zero()
    q = (x + y) ** 3 / (x - y) - (x ** 3 + 3 * x ** 2 * y + 3 * x * y ** 2 + y ** 3) / (x - y)
    assert F.is_zero(q)
    assert Mat._rows([[q]], F).is_zero()
    tiny = F.const(Fraction(1, 10 ** 40)) * x * y
    assert not F.is_zero(q + tiny)
    assert not Mat._rows([[q + tiny]], F).is_zero()


def test_context_grows_and_old_matrices_follow():
    F = SymbolicField()
    ring = F.poly_ring()
    syms = [F.param(f"p{i}") for i in range(40)]
    early = Mat._rows([[syms[0], syms[1]], [syms[2], 1 / (1 + syms[3] ** 2)]], F)
    early._nat()
    cap = ring.cap
    late = Mat._rows([[sum(syms[4:], se.Integer(0)), syms[-2]], [syms[-3], syms[-4] / (1 + syms[3] ** 2)]], F)
    late._nat()
    assert ring.cap > cap and early._n.ctx is not ring.ctx
    P = early @ late + late.T
    G = SymbolicField()
    G.native = False
    P2 = (Mat._rows(entries(early), G) @ Mat._rows(entries(late), G) + Mat._rows(entries(late), G).T)
    assert all(same(a, b) for r1, r2 in zip(entries(P), entries(P2)) for a, b in zip(r1, r2))


def test_entries_flint_cannot_hold_fall_back_to_symengine():
    F = SymbolicField()
    x = F.param("x")
    M = Mat._rows([[se.sqrt(x), 1], [x, 2]], F)
    N = Mat._rows([[x, 1], [0, x]], F)
    assert isinstance(M._nat(), ObjMat)
    out = M @ N - N.T
    assert se.expand(entries(out)[0][0] - (se.sqrt(x) * x - x)) == 0
    assert not out.is_zero()
    assert (M - M).is_zero()


def test_dual_numbers_over_the_backend():
    F = SymbolicField()
    D = DualField(F)
    s = Scene(3, 2, F, chart="cayley")
    flow = {"X": s.P, "P": -(s.X)}
    d1 = s.d(lambda t: t.X.T @ t.X, flow)
    assert d1.is_zero()                     # X^T X = I along any tangent vector
    d2 = s.d(lambda t: t.X.T @ t.P, flow)
    assert not d2.is_zero()
    assert D.base is F


def _la1(s):
    k = 1 + 2 * s.kappa
    X, P, A = s.X, s.P, s.A
    flow = {"X": P - k * (X @ P.T @ X), "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    return {"LA1": s.d(L, flow) - comm(s.Phi - s.lam * s.A, L(s))}


def _la1_corrupt(s):
    out = _la1(s)
    out["LA1"] = out["LA1"] + s.X @ s.X.T * s.q(1, 10 ** 30) * s.lam * s.kappa
    return out


def _la1_cayley(s):
    out = _la1(s)
    out["a"] = s.a[0] - s.A[0, 0]           # reads coordinates: the Cayley chart
    return out


@pytest.mark.parametrize("func,verdict,sizes", [(_la1, "proved", ((2, 1), (3, 1), (3, 2))),
                                                (_la1_corrupt, "fails", ((2, 1), (3, 2))),
                                                (_la1_cayley, "proved", ((2, 1), (2, 2)))])
def test_verdicts_with_either_representation(func, verdict, sizes, monkeypatch):
    claim = Claim(id="t-la1", paper=("LA1",), kind="lax", section="5", func=func, sizes=admissible(3),
                  title="LA1")
    for n, r in sizes:
        got = run_exact(claim, n, r, 0).verdict
        monkeypatch.setattr(SymbolicField, "native", False)
        old = run_exact(claim, n, r, 0).verdict
        monkeypatch.setattr(SymbolicField, "native", True)
        assert got == old == verdict, (n, r, got, old)


def test_sparse_entrywise_operations_and_products_agree_with_numpy():
    """Sums, differences, scalar multiples and products skip zero entries, and products by one in
    outer products: on random sparse polynomial matrices (zeros, ones, outer products, zero rows)
    they give numpy's entrywise results exactly."""
    import numpy as np
    from stiefelsym.backends import polyfield as pf
    R = SymbolicField().poly_ring()
    xs = [R.var(se.Symbol(f"t{i}")) for i in range(4)]
    rng = random.Random(11)

    def entry():
        k = rng.random()
        if k < 0.4:
            return R.zero
        if k < 0.55:
            return R.one
        return rng.choice(xs) * rng.randint(-3, 3) + rng.choice(xs) - R.one * rng.randint(0, 2)

    def mat(m, k):
        a = np.empty((m, k), dtype=object)
        for idx in np.ndindex(m, k):
            a[idx] = entry()
        if m > 1 and rng.random() < 0.3:
            a[rng.randrange(m), :].fill(R.zero)
        return a

    for _ in range(60):
        m, k, n = rng.randint(1, 4), rng.randint(1, 3), rng.randint(1, 4)
        a, b, c = mat(m, k), mat(m, k), mat(k, n)
        f = rng.choice([R.zero, R.one, xs[0] - xs[1]])
        assert (pf._ew_add(a, b) == a + b).all() and (pf._ew_sub(a, b) == a - b).all()
        assert (pf._ew_sub(a, a) == a - a).all() and (pf._ew_scale(a, f) == a * pf._scalar_array(f)).all()
        assert (pf._dot(a, c, R.zero) == np.dot(a, c)).all()
        assert (pf._dot(a.T.copy()[:, :m].T.copy(), c, R.zero) == np.dot(a, c)).all()


def test_a_pairing_of_symmetric_or_skew_matrices_sums_half_the_products_and_nothing_else():
    """The Frobenius sum of two symmetric (or two skew) matrices is summed over one triangle and
    doubled, and is zero off the diagonal for a symmetric against a skew one: on random matrices of
    each kind it equals the sum of all n^2 products; a matrix that is symmetric but for one entry
    (or skew but for one entry, or skew with one diagonal entry) is summed in full, so the one
    entry that breaks the pattern is still counted."""
    import numpy as np
    from stiefelsym.backends import polyfield as pf
    R = SymbolicField().poly_ring()
    xs = [R.var(se.Symbol(f"t{i}")) for i in range(4)]
    rng = random.Random(5)

    def entry():
        return R.zero if rng.random() < 0.2 else rng.choice(xs) * rng.randint(-3, 3) + R.one * rng.randint(-2, 2)

    def mat(m, kind):
        a = np.empty((m, m), dtype=object)
        for i in range(m):
            a[i, i] = R.zero if kind == "skew" else entry()
            for j in range(i + 1, m):
                a[i, j] = entry()
                a[j, i] = a[i, j] if kind == "sym" else (-a[i, j] if kind == "skew" else entry())
        return a

    def full(a, b):
        acc = R.zero
        for x, y in zip(a.flat, b.flat):
            acc = acc + x * y
        return acc

    seen = set()
    for _ in range(80):
        m = rng.randint(1, 5)
        ka, kb = rng.choice(["sym", "skew", "gen"]), rng.choice(["sym", "skew", "gen"])
        a, b = mat(m, ka), mat(m, kb)
        if m > 1 and rng.random() < 0.3:                   # one entry breaks the pattern of a
            i, j = rng.sample(range(m), 2) if rng.random() < 0.7 else (0, 0)
            a[i, j] = a[i, j] + xs[3] + R.one
        seen.add((pf._parity(a), pf._parity(b)))
        assert pf._frobenius(a, b, R.zero) == full(a, b)
    assert {(1, 1), (-1, -1), (1, -1), (-1, 1), (0, 0)} <= seen
    s, k = mat(4, "sym"), mat(4, "skew")
    k[1, 2], k[2, 1] = xs[1] + R.one, -(xs[1] + R.one)
    broken = s.copy()
    broken[2, 1] = broken[2, 1] + xs[0]                       # symmetric but for one entry
    assert pf._parity(s) == 1 and pf._parity(k) == -1 and pf._parity(broken) == 0
    assert pf._frobenius(s, k, R.zero) == 0 and pf._frobenius(broken, k, R.zero) != 0


def _printed_value_errors() -> int:
    """How many of a set of random rational functions print (PolyRing.text) as a different value:
    the text is read back by symengine and compared with the expression it came from at random
    rational points."""
    from stiefelsym.backends.polyfield import PolyRing
    R = PolyRing()
    xs = [se.Symbol(f"x{i}") for i in range(4)]
    rng = random.Random(11)
    wrong = 0
    for _ in range(20):
        def poly():
            return sum(se.Rational(rng.randint(-9, 9), rng.randint(1, 4)) * xs[rng.randrange(4)] ** rng.randint(0, 3)
                       * xs[rng.randrange(4)] ** rng.randint(0, 2) for _ in range(rng.randint(1, 5)))
        num, den = poly(), poly() if rng.random() < 0.5 else se.Integer(1)
        if den == 0:
            continue
        expr = num / den
        text = R.text(R.from_se(expr))
        if not same(se.sympify(text), expr):
            wrong += 1
    return wrong


def test_an_exact_residual_prints_its_own_value():
    """The canonical text of a rational function (the residual printed in every report) is read
    back by symengine and equals the function; a printer that drops a sign is caught."""
    assert _printed_value_errors() == 0


def test_a_printer_that_loses_a_sign_is_caught(monkeypatch):
    from stiefelsym.backends.polyfield import PolyRing
    real = PolyRing.text

    def wrong(self, r):
        t = real(self, r)
        return t.replace("- ", "+ ", 1)
    monkeypatch.setattr(PolyRing, "text", wrong)
    assert _printed_value_errors() > 0


INDEXES = [(0, 0), (2, 1), (-1, -2), (slice(None), 1), (1, slice(None)), (slice(0, 2), slice(1, 3)),
           (slice(None), slice(None)), (slice(1, None), 0), (slice(2, 2), slice(None))]


@pytest.mark.parametrize("kind", ["poly", "rat", "obj"])
def test_entries_and_blocks_read_natively_agree_with_the_generic_read(kind):
    """M[i, j] and M[block] straight from flint's storage (no conversion of the rest of the matrix)
    give the values, shapes and types of the read through the symengine entries; a wrong index
    raises as numpy does; a corrupted native read is caught."""
    F = SymbolicField()
    syms = [F.param(f"x{i}") for i in range(5)]
    K, _, _ = ops(F, syms, random.Random(3))
    if kind == "rat":
        K = K / syms[2] + K.T       # entries over different denominators
    elif kind == "obj":
        K = Mat._rows([[se.sqrt(syms[0]), syms[1], 3], [1, syms[2], 0], [syms[3], 2, se.sqrt(syms[1])]], F)
    want_type = {"poly": PolyMat, "obj": ObjMat}.get(kind)
    if want_type is not None:
        assert isinstance(K._nat(), want_type)
    for idx in INDEXES:
        fresh = K * 1                                   # a matrix with native storage only
        assert fresh._obj is None
        got = fresh[idx]
        assert fresh._obj is None, "the native read converted the whole matrix"
        ref = (K * 1)
        ref._view()
        want = ref[idx]
        if isinstance(want, Mat):
            assert isinstance(got, Mat) and got._shape() == want._shape() and got._tags == want._tags
            assert all(same(x, y) for r1, r2 in zip(entries(got), entries(want)) for x, y in zip(r1, r2))
            assert (got - want).is_zero()
        else:
            assert not isinstance(got, Mat) and same(got, want)
    with pytest.raises(IndexError):
        (K * 1)[7, 0]


def test_a_native_read_that_returns_the_wrong_entry_is_caught(monkeypatch):
    F = SymbolicField()
    syms = [F.param(f"x{i}") for i in range(5)]
    K, _, _ = ops(F, syms, random.Random(3))
    ref = K * 1
    ref._view()
    monkeypatch.setattr(PolyBackend, "entry", lambda self, s, i, j: PolyBackend._entry_original(self, s, j, i))
    monkeypatch.setattr(PolyBackend, "_entry_original", native_entry, raising=False)
    assert not same((K * 1)[0, 1], ref[0, 1])


native_entry = PolyBackend.entry


def first_row_unit(s):
    row = s.X[0:1, :]           # a block read from the native storage
    return {"r": s.tr(row @ row.T) - 1}


@pytest.mark.parametrize("method", ["exact", "rational", "modular", "float"])
def test_a_row_read_as_a_block_is_not_taken_for_a_column(method):
    """|first row of X| = 1 holds at r = n only (the columns of X are orthonormal, not its rows): a block
    read natively must give the row, whatever the method."""
    from stiefelsym.claims import Size
    from stiefelsym.run.runner import run_one
    c = Claim(id="first-row-unit", paper=(), kind="id", section="test", func=first_row_unit, sizes=admissible(4))
    assert run_one(c, Size(3, 2), method, 0).verdict == "fails"
    assert run_one(c, Size(3, 3), method, 0).verdict in ("proved", "checked", "numeric")


def test_a_rank_of_scalars_kept_in_flint():
    """A rank statement of a matrix built from flint scalars (the Jacobian of the constraints' brackets)
    is decided by the symbolic rank helpers, which read its entries as symengine expressions."""
    from stiefelsym.claims import load_catalog
    from stiefelsym.methods.fixed_size import run_exact
    from stiefelsym import Rank

    def constraint_brackets_invertible(s):
        return {"C0": Rank(s.mat(s.constraint_bracket_matrix()), s.r * (s.r + 1), generic=False)}
    res = run_exact(load_catalog().get("dirac-bracket-multipliers"), 1, 1, 0, func=constraint_brackets_invertible)
    assert res.verdict == "proved", res.message


def test_a_minor_of_entries_is_decided_in_flint():
    """Entries, their products and a matrix built from them stay flint scalars: a true statement about a
    minor of X is proved, a false one (the same minor said to be 1) fails, under the exact method."""
    from stiefelsym.methods.fixed_size import run_exact

    def minors(s):
        X = s.X
        m = X[0, 0] * X[1, 1] - X[0, 1] * X[1, 0]
        col = s.mat([[X[0, 0] * X[0, 0] + X[1, 0] * X[1, 0] + X[2, 0] * X[2, 0]]], ("?", "?"))
        one = s.mat([[s.q(1)]], ("?", "?"))
        return {"|column 1|^2 - 1": col - one, "minor - minor": s.mat([[m * m - m * m]], ("?", "?"))}

    def minor_is_one(s):
        X = s.X
        return {"minor - 1": s.mat([[X[0, 0] * X[1, 1] - X[0, 1] * X[1, 0] - 1]], ("?", "?"))}
    true = Claim(id="minor-true", paper=(), kind="id", section="test", func=minors, sizes=admissible(4))
    false = Claim(id="minor-false", paper=(), kind="id", section="test", func=minor_is_one, sizes=admissible(4))
    assert run_exact(true, 3, 2, 0).verdict == "proved"
    assert run_exact(false, 3, 2, 0).verdict == "fails"


@pytest.mark.parametrize("method", ["exact", "modular"])
def test_flint_scalars_cannot_be_steered(method):
    """Tricks on the exact backend's flint scalars: a quotient by an identically zero trace, a symengine
    parameter on the left of a flint scalar, a power of an entry.  None passes under any method."""
    from stiefelsym.claims import Size
    from stiefelsym.results import PASSING
    from stiefelsym.run.runner import run_one

    def div_zero(s):
        z = s.tr(s.X.T @ s.X - s.Ir)
        return {"q": s.mat([[s.q(1) / z - s.q(1) / z]], ("?", "?"))}

    def lam_left(s):   # lam tr(XᵀAX) = tr(XᵀAX): false
        t = s.tr(s.X.T @ s.A @ s.X)
        return {"q": s.mat([[s.lam * t - t]], ("?", "?"))}

    def entry_power(s):   # X₁₁² = X₁₁: false
        x = s.X[0, 0]
        return {"q": s.mat([[x ** 2 - x]], ("?", "?"))}
    for f in (div_zero, lam_left, entry_power):
        c = Claim(id=f"rf-{f.__name__}", paper=(), kind="id", section="test", func=f, sizes=admissible(4))
        assert run_one(c, Size(3, 2), method, 0).verdict not in PASSING, f.__name__


def _large_rational_functions(count: int = 12):
    """Random rational functions whose numerators have hundreds of terms over 6 variables (many terms of
    each total degree, so that flint's own order and the printed order differ within a degree)."""
    rng = random.Random(23)
    xs = [se.Symbol(f"x_{i}") for i in (1, 2, 10, 11, 3, 20)]
    out = []
    for _ in range(count):
        def linear():
            return sum(rng.randint(-4, 4) * x for x in xs) + rng.randint(-3, 3)
        num = se.expand(linear() * linear() * linear() * linear() + rng.randint(-5, 5) * xs[0] ** 5)
        den = linear() * linear() if rng.random() < 0.5 else se.Integer(1)
        out.append(num / den if den != 0 else num)
    return out


def test_a_residual_cut_short_is_the_start_of_its_whole_text():
    """The exact method prints a refuted residual cut to its first characters (fixed_size._short); its text
    asked for that width (PolyRing.text(r, width): the numerator's first terms only, each total degree read
    whole from flint's degrevlex order and sorted) is a prefix of the whole text, at least that long, so the
    printed residual is the same.  Negative control: the first terms in flint's own order, sorted without
    finishing their degree, print another residual."""
    from stiefelsym.backends.polyfield import PolyRing, _name_key, _term_key
    from stiefelsym.methods.fixed_size import SHORT, _short
    R = PolyRing()
    naive_differs = 0
    for expr in _large_rational_functions():
        r = R.from_se(expr)
        whole = R.text(r)
        for width in (1, 20, SHORT + 1, 1000):
            part = R.text(r, width)
            assert whole.startswith(part) and len(part) >= min(width, len(whole)), (width, part[:80], whole[:80])
        assert _short(R.text(r, SHORT + 1)) == _short(whole)
        assert whole.startswith(R.text(R.from_se(expr), SHORT + 1, reduced=True))   # as the exact method asks
        n = R.rf_reduce(r)[0]
        assert len(n) > SHORT + 1        # the numerators are long: the prefix is what is exercised
        names = [str(x) for x in R.syms]
        naive = sorted(((tuple(sorted(((names[i], int(e)) for i, e in enumerate(n.monomial(k)) if e),
                                      key=lambda t: _name_key(t[0]))), n.coefficient(k)) for k in range(SHORT + 1)),
                       key=_term_key)
        naive_differs += not whole.lstrip("(").startswith(R._terms_text(naive))
    assert naive_differs > 0


def test_the_exact_method_prints_the_same_refuted_residual_with_its_text_cut_short(monkeypatch):
    """A refuted claim whose residual has hundreds of terms: the exact method's printed residual is the one
    of the whole text cut short."""
    from stiefelsym.backends.polyfield import PolyRing
    claim = Claim(id="long-residual", paper=("test",), kind="id", section="test", sizes=admissible(n_max=3),
                  func=lambda s: {"(XᵀAX + PᵀAP)^3": (s.X.T @ s.A @ s.X + s.P.T @ s.A @ s.P) @ (
                      s.X.T @ s.A @ s.X + s.P.T @ s.A @ s.P) @ (s.X.T @ s.A @ s.X + s.P.T @ s.A @ s.P)})
    cut = run_exact(claim, 3, 2, 0)
    real = PolyRing.text
    monkeypatch.setattr(PolyRing, "text", lambda self, r, width=None, reduced=False: real(self, r))
    whole = run_exact(claim, 3, 2, 0)
    assert cut.verdict == whole.verdict == "fails"
    assert cut.residual == whole.residual and cut.residual.endswith("..."), (cut.residual, whole.residual)


def _terms_by_keys(R, p) -> list:
    """PolyRing._terms as first written (every term's monomial sorted by the names' keys, the terms by
    _term_key): the reference the ranked keys must reproduce."""
    from stiefelsym.backends.polyfield import _name_key, _term_key
    names = [str(x) for x in R.syms]
    out = [(tuple(sorted(((names[i], int(e)) for i, e in enumerate(exps) if e), key=lambda t: _name_key(t[0]))), c)
           for exps, c in p.terms()]
    out.sort(key=_term_key)
    return out


def test_the_terms_in_their_printed_order_are_those_of_the_names_keys():
    """The terms' order computed from the variables' ranks is the order of _term_key on the names (natural
    order: x_2 before x_10, x_10 before x_11 and x_20), term by term, on long numerators."""
    from stiefelsym.backends.polyfield import PolyRing
    R = PolyRing()
    for expr in _large_rational_functions(6):
        n = R.rf_reduce(R.from_se(expr))[0]
        assert R._terms(n) == _terms_by_keys(R, n)
        assert R._terms(n, 50) == _terms_by_keys(R, n)[:len(R._terms(n, 50))]


def test_a_polynomial_beyond_the_rings_parameters_is_decided_without_sympy(monkeypatch):
    """A value flint cannot hold (a product of two generic operators' coefficients, beyond MAX_VARS) whose
    numerator expands to a polynomial over Q is 0 only as the empty sum: decided by symengine's expansion,
    both ways, without sympy's cancel; an expression that is not such a polynomial still goes to sympy."""
    import symengine as se
    import sympy
    from stiefelsym.backends.polyfield import SymbolicField, _rational_polynomial

    calls = []
    real = sympy.cancel
    monkeypatch.setattr(sympy, "cancel", lambda *a, **k: calls.append(a) or real(*a, **k))
    u = se.symbols(" ".join(f"u{i}" for i in range(200)))
    nonzero = sum(u[i] * u[i + 100] for i in range(100)) - u[0] * u[100] / 3
    zero = sum(u[i] * u[i + 100] for i in range(100)) * 2 - 2 * sum(u[i + 100] * u[i] for i in range(100))
    assert SymbolicField._is_zero_sympy(nonzero) is False and not calls
    assert SymbolicField._is_zero_sympy(nonzero / (1 + u[1] ** 2)) is False and not calls
    assert SymbolicField._is_zero_sympy(zero) is True
    assert SymbolicField._is_zero_sympy((u[0] ** 2 - 1) / (u[0] - 1) - (u[0] + 1)) is True
    assert _rational_polynomial(u[0] ** 2 - u[1] / 3) and not _rational_polynomial(se.sqrt(u[0]) + 1)
    assert not _rational_polynomial(2.0 * u[0]) and not _rational_polynomial(se.I * u[0])
    assert not _rational_polynomial(u[0] ** -1) and not _rational_polynomial(se.sin(u[0]))
    # not a polynomial over Q: the sympy path decides it, as before
    assert SymbolicField._is_zero_sympy(se.sin(u[0]) ** 2 + se.cos(u[0]) ** 2 - 1) in (True, False)
    assert calls


def test_a_ring_started_wide_gives_the_values_of_one_that_grew():
    """A field whose flint ring starts wide (the width another evaluation of the graph reached) computes the
    same rational functions as one whose ring grows from 16 variables: the same texts, the same zero tests."""
    from stiefelsym.backends.polyfield import MAX_VARS, SymbolicField

    texts = []
    for width in (0, 300):
        f = SymbolicField(width)
        R = f.poly_ring()
        assert R.cap == (16 if width == 0 else 512)
        xs = [f.param(f"p{i}") for i in range(200)]
        num = sum((xs[i] * xs[i + 1] - xs[199 - i] for i in range(150)), xs[0] ** 3)
        den = 1 + xs[7] ** 2 + xs[150] * xs[3]
        r = R.from_se(num / den)
        zero = R.from_se(num / den - num * (1 + xs[150] * xs[3] + xs[7] ** 2) ** -1)
        texts.append((R.text(r), zero[0].is_zero(), f.is_zero(num - num), f.is_zero(num)))
        assert R.cap == (256 if width == 0 else 512) and len(R.syms) == 200 <= MAX_VARS
    assert texts[0] == texts[1] and texts[0][1:] == (True, True, False)


def test_a_term_cap_refuses_a_product_before_it_starts_and_by_a_count():
    """Under term_cap(k) a symbolic product, a trace of a product or a step of an inverse whose operands would
    take more than k term products raises SymbolicBudget (the count of the operands, the same on every
    machine); at the cap, and outside it, the results are those without a cap."""
    from stiefelsym.backends.polyfield import term_cap
    F = SymbolicField()
    xs = [F.param(f"x{i}") for i in range(6)]
    dense = sum(xs[1:], xs[0])                 # 6 terms, and 21 in its square

    def M():
        return Mat._rows([[dense, xs[0]], [xs[1], dense * dense]], F)
    # M @ M: the column sums of terms of M (6 + 1, 1 + 21) times its row sums (6 + 1, 1 + 21): 7*7 + 22*22 = 533
    with term_cap(533):
        P = M() @ M()
    Q = M() @ M()                              # held in flint: its trace with another is a Frobenius product
    with term_cap(532):
        with pytest.raises(SymbolicBudget, match="a symbolic product of 533 term products \\(the cap is 532\\)"):
            M() @ M()
        with pytest.raises(SymbolicBudget, match="trace of a product"):
            Q._trace_product(Q)
        with pytest.raises(SymbolicBudget, match="step of a symbolic inverse"):
            Mat._rows([[dense * dense, dense], [dense, xs[2] * dense]], F).inv()
    assert (P - M() @ M()).is_zero()
    small = Mat._rows([[xs[0], 1], [1, xs[1]]], F)
    with term_cap(10):
        assert (small @ small.inv() - Mat.identity(2, F)).is_zero()
    # a product of two rational functions counts too (6 x 21 = 126 term products): a scalar times a matrix,
    # or two entries multiplied, is where a mutant whose resolvent no longer cancels spends its time
    from stiefelsym.backends.polyfield import PolyRing
    R = PolyRing()
    ys = [R.var(se.Symbol(f"y{i}")) for i in range(6)]
    six = (sum(ys[1:], ys[0]), ())
    square = R.rf_mul(six, six)
    with term_cap(126):
        assert R.rf_mul(six, square)[0] == R.rf_mul(square, six)[0]
    with term_cap(125):
        with pytest.raises(SymbolicBudget, match="a product of rational functions of 126 term products"):
            R.rf_mul(six, square)


def test_a_product_cancels_the_atoms_of_its_denominator_that_divide_its_numerator():
    """a(λ)·e(λ) with a = (x + y)(x − y) and e = 1/((x + y)²(x + 2)): one atom x + y cancels, the product keeps
    (x + y)(x + 2) in its denominator and equals (x − y)/((x + y)(x + 2)); a product whose numerator no atom
    divides keeps its denominator."""
    from stiefelsym.backends.polyfield import PolyRing
    R = PolyRing()
    x, y = (R.var(se.Symbol(n)) for n in "xy")
    one = (R.one, ())
    e = R.rf_inv(((x + y) * (x + y) * (x + 2), ()))
    a = ((x + y) * (x - y), ())
    for q in (R.rf_mul(a, e), R.rf_mul(e, a)):
        num, den = q
        assert sorted(k for _, k in den) == [1, 1]
        assert R.den_poly(den) == (x + y) * (x + 2)
        assert num == x - y
    kept = R.rf_mul(((x - 3), ()), e)
    assert sorted(k for _, k in kept[1]) == [1, 2] and kept[0] == x - 3
    assert R.rf_mul(one, e) == e


def test_a_product_cancels_on_its_factors_as_the_product_itself_would():
    """The atoms of a product's denominator are divided out of its two factors (an irreducible atom divides
    n1 n2 as often as it divides n1 plus n2): the numerator and atoms are exactly those of cancelling the
    expanded product, for reduced and unreduced factors (an atom of a factor's own denominator dividing its
    numerator: a sum over a common denominator), atoms shared by both denominators, and a numerator
    divisible by an atom more often than its exponent; a numerator no atom divides keeps every atom (the
    failed divisions are a negative control), one an atom divides loses it."""
    from stiefelsym.backends.polyfield import PolyRing
    R = PolyRing()
    x, y, z = (R.var(se.Symbol(n)) for n in "xyz")
    (_, (u,)), (_, (v,)), (_, (w,)) = R.factor(x - y), R.factor(y - z), R.factor(x * x + y * z + 1)
    k, l, m = u[0], v[0], w[0]
    nums = [R.one, x + 3, (x - y) ** 3 * (z + 1), (y - z) * (x - y), (x * x + y * z + 1) * (x - z),
            (x - y) * (y - z) ** 2 * (x * x + y * z + 1)]
    dens = [(), ((k, 1),), ((k, 2), (l, 1)), ((l, 3),), ((k, 1), (m, 2)), ((k, 1), (l, 1), (m, 1))]
    rng = random.Random(4)
    for _ in range(40):
        a = (rng.choice(nums) * (rng.randint(1, 5) * x - y + rng.randint(-2, 2)), rng.choice(dens))
        b = (rng.choice(nums) * (z - rng.randint(-3, 3)), rng.choice(dens))
        expected = R.cancel(a[0] * b[0], R_merge(a[1], b[1]))
        assert R.rf_mul(a, b) == expected
        assert R.rf_mul(b, a) == expected
    # the negative control: x + 3 and z + 1 are divisible by none of the atoms, so nothing cancels
    assert R.rf_mul((x + 3, ((k, 1),)), (z + 1, ((l, 2),))) == ((x + 3) * (z + 1), ((k, 1), (l, 2)))
    # a divisible one: (x - y)^3 / ((x - y)^2 (y - z)) times (y - z) / (x - y) is 1, every atom divided out
    assert R.rf_mul(((x - y) ** 3, ((k, 2), (l, 1))), (y - z, ((k, 1),))) == (R.one, ())


def R_merge(d1: tuple, d2: tuple) -> tuple:
    from stiefelsym.backends.denominators import _merge_add
    return _merge_add(d1, d2)


def test_a_product_of_transposes_is_the_transpose_of_the_product_met_before():
    """a b = (bᵀ aᵀ)ᵀ: once a b is computed, bᵀ aᵀ is its transpose (no new product), with the value symengine gives;
    a product of other operands (aᵀ bᵀ, a product with a copy of a) is computed, and each value is symengine's."""
    F, G = fields()
    syms = [F.param(f"x{i}") for i in range(5)]
    for seed in range(3):
        rng = random.Random(seed)
        dens = [syms[0] - syms[1], 1 + syms[2] ** 2]
        a, b = rand_mat(F, 2, 3, syms, rng, dens), rand_mat(F, 3, 2, syms, rng, dens)
        ag, bg = (Mat._rows(entries(M), G) for M in (a, b))
        ab = a @ b
        calls = []
        import stiefelsym.backends.polyfield as pf
        dot = pf._dot
        pf._dot = lambda x, y, z: calls.append(1) or dot(x, y, z)
        try:
            ba_t = b.T @ a.T
            assert not calls                                    # the transpose of a b, no product
            others = [a.T @ b.T, b @ a, Mat._rows(entries(a), F) @ b]
            assert len(calls) == 2          # aᵀ bᵀ and the copy's product computed; b a is (aᵀ bᵀ)ᵀ
        finally:
            pf._dot = dot
        assert all(same(x, y) for r1, r2 in zip(entries(ba_t), entries((bg.T @ ag.T))) for x, y in zip(r1, r2))
        assert all(same(x, y) for r1, r2 in zip(entries(ab.T), entries(ba_t)) for x, y in zip(r1, r2))
        for M, Mg in zip(others, (ag.T @ bg.T, bg @ ag, ag @ bg)):
            assert all(same(x, y) for r1, r2 in zip(entries(M), entries(Mg)) for x, y in zip(r1, r2))


@pytest.mark.parametrize("nvars, cap", [(10, 16), (17, 24), (37, 40), (64, 64), (65, 128), (200, 256)])
def test_a_ring_grows_by_a_word_of_exponents_up_to_64_variables(nvars, cap):
    """Up to 64 variables the context grows by 8 (a word of flint's exponent vectors at 8 bits an exponent), by
    doubling beyond: a product's cost follows the words of its monomials (37 parameters in a context of 64 made
    pencil-rank-a1's kernel product at (6, 5) 1.4 times slower than in one of 40).  The values do not depend on
    the width (see test_a_ring_started_wide_gives_the_values_of_one_that_grew)."""
    from stiefelsym.backends.polyfield import SymbolicField
    f = SymbolicField()
    R = f.poly_ring()
    xs = [f.param(f"p{i}") for i in range(nvars)]
    p = R.from_se(sum(x * x for x in xs))
    assert R.cap == cap and len(R.syms) == nvars and R.text(p).count("**2") == nvars


def _poly_mats(rows_a, rows_b):
    import numpy as np
    F = SymbolicField()
    be = F.native_backend()
    a, b = (be.from_obj(np.array([[se.sympify(x) for x in row] for row in rows], dtype=object))
            for rows in (rows_a, rows_b))
    assert type(a) is PolyMat and type(b) is PolyMat
    return be, a, b


def test_a_product_with_renamed_copies_of_rows_vanishes_exactly_as_the_whole_product():
    """PolyBackend.product_vanishes computes only the rows of a that are not σ(another row), σ a substitution of
    variables b does not contain (λ1 -> λ2 here), and the columns of b likewise: the same answer as the whole
    product, both ways, on an a with rows at several values of λ."""
    x, y, l1, l2, l3 = se.symbols("x y l1 l2 l3")
    row = lambda l: [l * x + y, -(l * x + y) * y]           # noqa: E731  (row · (y, 1) = 0)
    kernel = [[y, y * y * x], [1, x * y]]
    be, a, b = _poly_mats([row(l1), row(l2), row(l3)], kernel)
    assert be.product_vanishes(a, b) and be.is_zero(be.matmul(a, b))
    wrong = [[y, y * y * x], [1 + x, x * y]]                # the first column is no longer in the kernel
    be, a, b = _poly_mats([row(l1), row(l2), row(l3)], wrong)
    assert not be.product_vanishes(a, b) and not be.is_zero(be.matmul(a, b))


def test_a_row_that_only_looks_like_a_renamed_copy_is_multiplied():
    """Negative controls: a row equal to σ(another row) but for one coefficient, and a row σ(another row) where σ
    renames a variable that b contains, are multiplied, not skipped: the nonzero product is found."""
    x, y, l1, l2 = se.symbols("x y l1 l2")
    # the second row is the first at λ2 but for the coefficient 3 (a wrong copy): its product is not 0
    be, a, b = _poly_mats([[l1 * x + y, -(l1 * x + y) * y], [l2 * x + y, -(l2 * x + 3 * y) * y]], [[y], [1]])
    assert not be.product_vanishes(a, b)
    # row · (l2, -l1 l2)ᵀ: the first row (l1, 1) gives 0, the second (l2, 1) = σ(first) with σ: l1 -> l2, which b
    # contains: not a copy, and its product l2² − l1 l2 is not 0
    be, a, b = _poly_mats([[l1, 1], [l2, 1]], [[l2], [-l1 * l2]])
    assert not be.product_vanishes(a, b) and not be.is_zero(be.matmul(a, b))
    # the same with the columns: b's second column is the first at l2 but for a sign
    be, a, b = _poly_mats([[x, y]], [[y * l1, y * l2], [-x * l1, x * l2]])
    assert not be.product_vanishes(a, b)
    be, a, b = _poly_mats([[x, y]], [[y * l1, y * l2], [-x * l1, -x * l2]])
    assert be.product_vanishes(a, b)


def test_rows_known_to_vanish_against_an_equal_kernel_are_not_multiplied_again():
    """A row found with r b = 0 is remembered for kernels equal to b entry by entry (built again from the same
    entries): the rows of a larger matrix equal to it need no product, and a row that differs from it, or the same
    row against a kernel that differs, is still multiplied (negative controls)."""
    from stiefelsym.backends import polyfield
    x, y = se.symbols("x y")
    rows, kernel = [[x * y, -x * x]], [[x], [y]]
    be, a, b = _poly_mats(rows, kernel)
    assert be.product_vanishes(a, b)
    known = polyfield._vanishing_rows(b.a, be.ring.ctx)
    assert known.holds(a.a[0])
    be2, a2, b2 = _poly_mats(rows + [[y, -x]], kernel)
    assert be2.product_vanishes(a2, b2)
    be3, a3, b3 = _poly_mats(rows + [[y, -x + 1]], kernel)       # a row not in the kernel's annihilator
    assert not be3.product_vanishes(a3, b3)
    be4, a4, b4 = _poly_mats(rows, [[x], [y + 1]])                # another kernel: the row is multiplied again
    assert not be4.product_vanishes(a4, b4)
