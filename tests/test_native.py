"""The whole-matrix backends against the generic representation (numpy arrays of field
elements), and reverse-mode gradients against forward mode."""
from __future__ import annotations

import math
import random
from fractions import Fraction

import numpy as np
import os

import pytest

from stiefelsym.backends import native
from stiefelsym import scene as scene_mod
from stiefelsym.backends.fields import DegreeField, Dual, DualField, ErrNum, FloatField, ModularField, RationalField
from stiefelsym.backends.matrix import Mat, block
from stiefelsym.methods.fixed_size import degree_bound, run_points
from stiefelsym.scene import Scene

from float_replay import assert_within_bounds, entries, replay_field

P61 = 2**61 - 1


def generic(field):
    """The same field with the whole-matrix backend switched off."""
    field.__dict__["_backend"] = None
    return field


def rand_mat(field, m, k, rng):
    return Mat._rows([[field.param("x", rng) for _ in range(k)] for _ in range(m)], field)


def ops(F, rng):
    """The same sequence of operations over a field: products, sums, transposes, scalars,
    traces, inverses and blocks."""
    A, B, C = rand_mat(F, 4, 4, rng), rand_mat(F, 4, 3, rng), rand_mat(F, 3, 4, rng)
    c = F.param("c", rng)
    M = (A @ B @ C - C.T @ B.T * c + A.inv() @ A.T) * F.const(Fraction(3, 7))
    K = block([[M, A @ B], [C, C @ B]])
    return K, (M @ M.inv()).trace() + M.trace() * c


@pytest.mark.parametrize("make", [lambda: ModularField(P61), RationalField])
def test_exact_backends_agree_with_the_generic_representation(make):
    for seed in range(3):
        K1, t1 = ops(make(), random.Random(seed))
        K2, t2 = ops(generic(make()), random.Random(seed))
        assert K1._n is not None and K2._n is None
        assert entries(K1) == entries(K2) and t1 == t2


def test_float64_bounds_contain_the_exact_value():
    """Every float64 input is an exact rational; redo the operations in Q and check that each
    entry lies within its bound."""
    for seed in range(5):
        F = FloatField()
        rng = random.Random(seed)
        K, t = ops(F, rng)
        rng = random.Random(seed)
        Kq, tq = ops(replay_field(F), rng)
        for row, rowq in zip(entries(K), entries(Kq)):
            for x, q in zip(row, rowq):
                assert abs(Fraction(x.v) - Fraction(int(q.p), int(q.q))) <= Fraction(x.e)
        assert abs(Fraction(t.v) - Fraction(int(tq.p), int(tq.q))) <= Fraction(t.e)


def test_float64_inverse_of_a_nearly_singular_matrix_is_refused_or_bounded():
    F = FloatField()
    M = Mat._rows([[F.const(1), F.const(1)], [F.const(1), ErrNum(1.0 + 2.0**-50, 0.0, 1.0)]], F)
    try:
        Z = M.inv()
    except ArithmeticError:
        return
    exact = [[Fraction(x) for x in row] for row in np.linalg.inv(np.array([[1, 1], [1, 1 + 2.0**-50]])).tolist()]
    for row, rowe in zip(entries(Z), exact):
        for x, _ in zip(row, rowe):
            assert x.e > 0


def test_structural_inverse_bound_holds_for_a_symbolic_matrix():
    """M⁻¹ = adj(M)/det(M) for a 3x3 matrix of linear forms: the backend's marker says numerator
    degree <= 2 over a factor of degree <= 3, and sympy agrees."""
    import sympy as sp
    xs = sp.symbols("x0:9")
    M = sp.Matrix(3, 3, lambda i, j: xs[3 * i + j] + int(i == j))
    inv = M.adjugate()
    det = sp.expand(M.det())
    assert max(sp.Poly(sp.expand(e), *xs).total_degree() for e in inv) <= 2
    assert sp.Poly(det, *xs).total_degree() <= 3
    F = DegreeField()
    D = Mat._rows([[F.param("x") + F.const(int(i == j)) for j in range(3)] for i in range(3)], F)
    Z = D.inv()
    z = Z._nat().d
    assert z.num == 2 and F.den_degree(z.den) == 3


def test_structural_degree_bounds_stay_finite_and_cover_the_leading_term(catalog):
    """Structural and entrywise bounds both bound the same residual; the structural one is
    never below the degree the entrywise one certifies for a polynomial claim (no division)."""
    def poly(s):
        return {"v": s.X.T @ s.P @ s.P.T @ s.X + s.P.T @ s.P}
    from stiefelsym.claims import Claim, admissible
    c = Claim(id="poly", paper=("x",), kind="id", section="", func=poly, sizes=admissible(3),
              title="t", statement="t")
    nat = degree_bound(c, 3, 2)
    native.ENABLED = False
    try:
        gen = degree_bound(c, 3, 2)
    finally:
        native.ENABLED = True
    assert nat.numerator + nat.denominator >= gen.numerator - gen.denominator


def _hamiltonians(s):
    yield lambda t: (t.P.T @ t.P).trace() / 2 - (t.X.T @ t.P @ t.X.T @ t.P).trace() * t.kappa
    yield lambda t: (t.X.T @ t.A @ t.X).trace() * (t.P.T @ t.P).trace()
    yield lambda t: (t.X.T @ t.resolvent(t.lam) @ t.X).trace()
    yield lambda t: ((t.In + t.X @ t.X.T).inv() @ t.A).trace() + t.X[0, 0] * t.P[1, 0]
    yield lambda t: block([[t.X, t.P]]).T.__matmul__(block([[t.X, t.P]])).trace()


@pytest.mark.parametrize("make", [lambda: ModularField(P61), RationalField])
def test_reverse_gradients_equal_forward_gradients(make):
    for chart in ("cayley", "equivariant"):
        base = Scene(4, 2, make(), chart=chart, rng=random.Random(7))
        for H in _hamiltonians(base):
            rev = base.gradient(H)
            scene_mod.REVERSE_GRADIENTS = False
            try:
                fwd = Scene(4, 2, make(), chart=chart, rng=random.Random(7))
                fwd.params.update(base._point_values())
                fg = fwd.gradient(H)
            finally:
                scene_mod.REVERSE_GRADIENTS = True
            for a, b in zip(rev, fg):
                assert entries(a) == entries(b)


def test_verdicts_do_not_depend_on_the_backend(catalog):
    """The same seeded modular runs with and without the whole-matrix backends."""
    picked = [c for c in catalog if c.section in ("2", "3", "5")][:12]
    for c in picked:
        size = next(iter(c.sizes))
        n, r = size.n, size.r
        a = run_points(c, n, r, "modular", 3)
        native.ENABLED = False
        scene_mod.REVERSE_GRADIENTS = False
        try:
            b = run_points(c, n, r, "modular", 3)
        finally:
            native.ENABLED = True
            scene_mod.REVERSE_GRADIENTS = True
        assert a.verdict == b.verdict, c.id


# -- trying to fool the reverse mode: a Hamiltonian assembled from entries -----------------

def _entrywise_kinetic(t, c):
    """c * sum_ij P_ij^2, read entry by entry (reverse mode differentiates the entry reads)."""
    acc = t.q(0)
    for i in range(t.n):
        for j in range(t.r):
            acc = acc + t.P[i, j] * t.P[i, j]
    return acc * c


def _flow_claim(c_num, c_den):
    from stiefelsym.claims import Claim, admissible

    def func(s):
        entry = s.dirac_flow(lambda t: _entrywise_kinetic(t, t.q(c_num, c_den)))
        matrix = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2)
        return {"dX/dt": entry.Xdot - matrix.Xdot, "dP/dt": entry.Pdot - matrix.Pdot}
    return Claim(id="entrywise-kinetic", paper=("Euclidean",), kind="id", section="t", func=func,
                 sizes=admissible(3))


@pytest.mark.parametrize("method", ["modular", "rational", "float"])
def test_an_entrywise_hamiltonian_is_differentiated_exactly(method):
    from stiefelsym.methods.fixed_size import METHOD_RUNNERS
    run = METHOD_RUNNERS[method]
    assert run(_flow_claim(1, 2), 3, 2, 0).verdict in ("checked", "numeric")
    assert run(_flow_claim(1, 3), 3, 2, 0).verdict == "fails"       # the wrong coefficient is refuted


# -- the closed-form Dirac multipliers against the solved r(r+1) system ---------------------

def _flows(s, H):
    d, m = s.dirac_flow(H), s.multiplier_flow(H)
    return [d.Xdot, d.Pdot, m.Xdot, m.Pdot, m["Lambda"], m["Pi"]]


@pytest.mark.parametrize("make", [lambda: ModularField(P61), RationalField])
@pytest.mark.parametrize("chart", ["cayley", "equivariant"])
def test_closed_form_multipliers_equal_the_solved_system(make, chart):
    for n, r in ((4, 2), (3, 3), (5, 1)):
        base = Scene(n, r, make(), chart=chart, rng=random.Random(11), component=1 if r == n else 0)
        for H in _hamiltonians(base):
            closed = _flows(base, H)
            assert base._cached_for("closed", H, lambda: None) is not None
            scene_mod.CLOSED_FORM_MULTIPLIERS = False
            try:
                solved_scene = Scene(n, r, make(), chart=chart, rng=random.Random(11), component=1 if r == n else 0)
                solved_scene.params.update(base._point_values())
                solved = _flows(solved_scene, H)
            finally:
                scene_mod.CLOSED_FORM_MULTIPLIERS = True
            for a, b in zip(closed, solved):
                assert entries(a) == entries(b)


def test_closed_form_multipliers_in_floating_point_stay_within_the_bounds_of_the_solved_system():
    """In float64 the point is on V only up to rounding, but every value approximates the exact
    evaluation at a point exactly on V: the closed form and the solved system agree within the sum
    of their error bounds."""
    for n, r in ((4, 2), (5, 3), (3, 3)):
        a = Scene(n, r, FloatField(), rng=random.Random(2))
        for H in _hamiltonians(a):
            closed = _flows(a, H)
            assert a._cached_for("closed", H, lambda: None) is not None
            scene_mod.CLOSED_FORM_MULTIPLIERS = False
            try:
                b = Scene(n, r, FloatField(), rng=random.Random(2))
                b.params.update(a._point_values())
                solved = _flows(b, H)
            finally:
                scene_mod.CLOSED_FORM_MULTIPLIERS = True
            for A, B in zip(closed, solved):
                for x, y in zip(A._view().flat, B._view().flat):
                    assert abs(x.v - y.v) <= x.e + y.e


def test_closed_form_multipliers_need_the_standard_constraint_set():
    """Not for the metric realization."""
    H = lambda t: t.tr(t.P.T @ t.P) / 2      # noqa: E731
    m = Scene(4, 2, ModularField(P61), rng=random.Random(1), realization="metric")
    assert m._closed_form_multipliers(*m.gradient(H)) is None
    e = Scene(4, 2, ModularField(P61), rng=random.Random(1))
    assert e._closed_form_multipliers(*e.gradient(H)) is not None


def test_blocks_of_parameters_are_named_entries_of_the_point():
    """Parameters drawn as one native block (matrices of at least PARAM_BLOCK_MIN entries) are the
    point's named coordinates: asking for one by name gives the entry the block holds."""
    small = Scene(5, 2, ModularField(P61), rng=random.Random(3))
    assert small._skew_params("S", 5, "n")._n is None or not small._param_blocks
    s = Scene(12, 2, ModularField(P61), rng=random.Random(3))
    S = s._skew_params("S", 12, "n")
    assert S._n is not None
    vals = s._point_values()
    assert len(vals) == 66
    assert vals["S_1,2"] == S._view()[0, 1] and vals["S_2,4"] == S._view()[1, 3] == -S._view()[3, 1]
    assert s._param("S_1,2") == S._view()[0, 1]


def test_triangular_multipliers_of_the_twisted_form_equal_the_solved_system():
    from stiefelsym import twisted
    H = lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X)      # noqa: E731
    for n, r in ((4, 2), (3, 3)):
        a = Scene(n, r, ModularField(P61), rng=random.Random(5))
        fa = twisted.multiplier_flow(a, H, a.eta)
        scene_mod.CLOSED_FORM_MULTIPLIERS = False
        try:
            b = Scene(n, r, ModularField(P61), rng=random.Random(5))
            a.eta
            b.params.update(a._point_values())
            fb = twisted.multiplier_flow(b, H, b.eta)
        finally:
            scene_mod.CLOSED_FORM_MULTIPLIERS = True
        for key in ("Lambda", "Pi"):
            assert entries(fa[key]) == entries(fb[key])
        assert entries(fa.Xdot) == entries(fb.Xdot) and entries(fa.Pdot) == entries(fb.Pdot)


def test_term_scales_of_a_float_solve_stay_the_size_of_the_solution():
    """The scales carried through elimination would multiply by pivot ratios (10^2699 at n = 16
    in mpmath), making the resolution test e <= 10^-8 m vacuous; a solution entry's scale is its
    own size."""
    import mpmath
    with mpmath.workdps(30):
        s = Scene(16, 2, FloatField(30), rng=random.Random(0))
        for x in s.X._view().flat:          # |X_ij| <= 1: its terms stay of that size
            assert x.m <= 10


def structured_ops(F, rng):
    """Products the float64 backend computes without a full BLAS product: with a diagonal matrix
    on either side, with a signed selection of columns (the Cayley chart's [D; 0]), with zeros
    and the identity, a product met twice and one met as its transpose."""
    be = native.backend(F)
    xs = [F.param("d", rng) for _ in range(4)]
    if be is not None:
        D = Mat._wrap_native(be.diag(xs), F)
    else:                 # the exact replay (generic representation)
        D = Mat._rows([[xs[i] if i == j else F.const(0) for j in range(4)] for i in range(4)], F)
    J = Mat._consts(np.array([[1, 0, 0], [0, 0, 0], [0, -1, 0], [0, 0, 0]]), F)
    B, C = rand_mat(F, 4, 4, rng), rand_mat(F, 4, 3, rng)
    BC = B @ C
    out = [D @ B @ J, B @ D, (B - D) @ J, BC, C.T @ B.T, B @ C, BC.T @ (B @ C),
           Mat.zeros(4, 4, F) @ B, B @ Mat.identity(4, F), Mat.identity(4, F) @ B, D.T @ B]
    return out


def test_float64_structured_and_repeated_products_keep_the_bound():
    """Each of these products lies within its bound of the exact rational value, and a product
    met again (or as its transpose) is the stored one, not a new computation."""
    for seed in range(4):
        F = FloatField()
        out = structured_ops(F, random.Random(seed))
        exact = structured_ops(replay_field(F), random.Random(seed))
        assert all(M._n is not None for M in out)
        assert_within_bounds(out, exact, scales=True)
        assert out[5]._n is out[3]._n                  # B @ C again
        assert out[4]._n is out[3]._n.t                # (B C)^T from the stored B C


def test_float64_structured_products_equal_full_products():
    """Diagonal, selection, zero and identity products give the values and scales of the full
    BLAS product (up to the sign of zeros), with the same bound."""
    rng = np.random.default_rng(0)
    F = FloatField()
    be = native.backend(F)
    a = be.from_array(rng.standard_normal((5, 5)))
    d = be.diag([F.param("d", random.Random(k)) for k in range(5)])
    J = be.from_consts(np.array([[0, 1], [0, 0], [-1, 0], [0, 0], [0, 0]]))
    assert d.diag is not None and J.sel is not None
    for x, y in ((d, a), (a, d), (a, J), (be.zeros(5, 5), a), (a, be.identity(5))):
        s = be.matmul(x, y)
        full_v, full_m = x.v @ y.v, x.m @ y.m
        assert np.array_equal(s.v, full_v) and np.allclose(s.m, full_m, rtol=1e-15, atol=0)
        plain = native.F64(x.v.copy(), x.e, x.m.copy())
        full_e = be.matmul(plain, native.F64(y.v.copy(), y.e, y.m.copy())).e
        # the same bound (a diagonal's norm is its diagonal's: the same sum of squares, summed in
        # another order)
        assert abs(s.e - full_e) <= 1e-12 * full_e


def test_frobenius_bound_covers_tiny_and_huge_entries():
    """The Frobenius bound is above the exact norm, also where the squares fall below the normal
    range of float64 or overflow it."""
    rng = np.random.default_rng(1)
    for scale in (1.0, 1e-160, 1e-300, 2.0**-1074, 1e150):
        x = rng.standard_normal((7, 5)) * scale
        exact = sum(Fraction(float(t)) ** 2 for t in x.ravel())
        b = native._fro(x)
        assert b == math.inf or Fraction(b) ** 2 >= exact
    assert native._fro(np.full((2, 2), 1e300)) == math.inf


def test_degree_markers_of_diagonals_and_constants_equal_the_entrywise_sum():
    """The shortcuts of the structural backend give the marker its generic conversion gives."""
    F = DegreeField()
    be = native.backend(F)
    xs = [F.param("x"), F.const(3), F.param("y") / F.param("z"), F.const(Fraction(1, 2)), F.param("w"),
          F.param("v"), F.const(0), F.const(5)]
    for sub in (xs, xs[:1], xs[4:6], [F.const(0)], []):
        if not sub:
            continue
        a = np.empty((len(sub), len(sub)), dtype=object)
        a.fill(F.const(0))
        for i, x in enumerate(sub):
            a[i, i] = x
        d1, d2 = be.diag(sub).d, be.from_obj(a).d
        assert (d1.num, d1.den, d1.h) == (d2.num, d2.den, d2.h)
    for c in (np.array([[1, 0], [0, -1], [0, 0]]), np.array([[2, 3], [3, 0]]), np.zeros((2, 2), dtype=int)):
        G1, G2 = DegreeField(), DegreeField()
        d1 = native.backend(G1).from_consts(c).d
        d2 = native.backend(G2).from_obj(np.vectorize(lambda x: G2.const(int(x)), otypes=[object])(c)).d
        assert (d1.num, d1.den, d1.h) == (d2.num, d2.den, d2.h) and G1.constant_bits == G2.constant_bits


def test_one_blas_thread_limits_and_restores():
    """The float method's BLAS setting (threadpoolctl) is one thread inside and the previous count
    after (also when the run raises)."""
    from stiefelsym.backends import blas
    ctl = blas.controller()
    if ctl is None or blas.blas_threads() is None:
        pytest.skip("threadpoolctl finds no BLAS here")
    with ctl.limit(limits=2, user_api="blas"):
        before = blas.blas_threads()
        with native.one_blas_thread():
            assert blas.blas_threads() == 1
        assert blas.blas_threads() == before
        with pytest.raises(RuntimeError):
            with native.one_blas_thread():
                raise RuntimeError
        assert blas.blas_threads() == before


def test_importing_stiefelsym_leaves_the_environment_alone():
    """Importing the package sets no environment variable and no thread count (a subprocess)."""
    import subprocess
    import sys
    code = ("import os; before = dict(os.environ); import stiefelsym, stiefelsym.backends.native; "
            "assert dict(os.environ) == before, set(os.environ) ^ set(before)")
    env = {k: v for k, v in os.environ.items() if not k.endswith("_NUM_THREADS")}
    subprocess.run([sys.executable, "-c", code], check=True, env=env)


@pytest.mark.parametrize("make", [lambda: ModularField(P61), RationalField, FloatField])
def test_a_constant_times_a_dual_matrix_drops_only_a_zero_term(make):
    """(a c)' = a' c + a c' with c' = 0: the shortcut gives the full formula's value (exact
    fields) or a bound that still holds (float64)."""
    F = make()
    rng = random.Random(0)
    D = DualField(F)
    be, B = native.backend(D), native.backend(F)
    a0, a1 = rand_mat(F, 3, 2, rng)._nat(), rand_mat(F, 3, 2, rng)._nat()
    c = F.param("c", rng)
    got = be.smul((a0, a1), Dual(c, F.const(0)))
    full = (B.smul(a0, c), B.add(B.smul(a1, c), B.smul(a0, F.const(0))))
    if F.exact:
        assert got[0] == full[0] and got[1] == full[1]
    else:
        assert np.array_equal(got[1].v, full[1].v) and got[1].e <= full[1].e
