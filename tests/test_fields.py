"""Fields: exactness, degree bounds, dual numbers and the float error model."""
import random
from fractions import Fraction

import pytest

from stiefelsym.backends.fields import DegenerateError, Deg, DegreeField, Dual, FloatField, ModularField, RationalField
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.matrix import Mat


def _poly_program(F, x, y):
    """A small straight-line program with cancellation, a division and a linear solve."""
    a = (x * y + 3) * (x - y) - x * x * y
    b = a / (x + 2)
    M = [[x, y + 1], [y, x * x + 1]]
    sol = F.solve(M, [[b], [x]])
    return sol[0][0] * (x + 1) - sol[1][0]


def test_degree_bound_dominates_the_true_numerator_degree():
    S = SymbolicField()
    x, y = S.param("x"), S.param("y")
    import sympy
    value = sympy.together(sympy.sympify(_poly_program(S, x, y)))
    num, _ = sympy.fraction(value)
    true_degree = sympy.Poly(sympy.expand(num), sympy.Symbol("x"), sympy.Symbol("y")).total_degree()
    D = DegreeField()
    bound = _poly_program(D, D.param("x"), D.param("y"))
    assert isinstance(bound, Deg) and bound.num >= true_degree


def test_modular_and_rational_agree_on_a_rational_program():
    Q, P = RationalField(), ModularField()
    vq = _poly_program(Q, Q.const(3), Q.const(Fraction(5, 7)))
    vp = _poly_program(P, P.const(3), P.const(Fraction(5, 7)))
    assert P.const(Fraction(int(vq.p), int(vq.q))) == vp


def test_dual_numbers_differentiate():
    Q = RationalField()
    x = Dual(Q.const(2), Q.const(1))
    f = (x * x * x + 1) / (x + 1)          # f = x^2 - x + 1, f' = 2x - 1
    assert f.a == 3 and f.b == 3


def test_error_bound_contains_the_true_error():
    F = FloatField()
    rng = random.Random(1)
    for _ in range(50):
        a, b = Fraction(rng.randint(1, 10**6), 3**7), Fraction(rng.randint(1, 10**6), 7**5)
        ea, eb = F.const(a), F.const(b)
        v = (ea * eb - ea / eb) * (ea + eb)
        exact = (a * b - a / b) * (a + b)
        assert abs(Fraction(v.v) - exact) <= Fraction(v.e)


def test_division_by_zero_is_degenerate():
    with pytest.raises(DegenerateError):
        RationalField().solve([[0, 0], [0, 0]], [[1], [1]])
    with pytest.raises(DegenerateError):
        FloatField().const(1) / FloatField().const(0)


def test_symbolic_zero_test_handles_rational_functions():
    S = SymbolicField()
    x = S.param("x")
    assert S.is_zero(1 / (x + 1) - (x - 1) / (x * x - 1))
    assert not S.is_zero(1 / (x + 1) - 1 / (x - 1))


def test_matrix_transpose_and_trace():
    Q = RationalField()
    M = Mat.from_rows([[Q.const(1), Q.const(2)], [Q.const(3), Q.const(4)]], Q)
    assert (M.T @ M).trace() == 30
    with pytest.raises(TypeError):
        M * 0.5


# -- heights: the degree markers also bound log2 of the L1 norm of the integer numerator ----------

class _Ref:
    """The integer numerator N and the factored denominator that a Deg marker describes, computed
    exactly with sympy by the same rules (sums over the largest exponents, quotients as new factors)."""

    def __init__(self, N, den, reg, zero=False):
        # ``zero``: known to be zero by the markers' rules (a literal 0, or a product with one)
        self.N, self.den, self.reg, self.zero = N, dict(den), reg, zero

    def lift(self, o):
        return o if isinstance(o, _Ref) else self.reg.const(o)

    def times_factors(self, den):
        N = self.N
        for k, e in den.items():
            N = N * self.reg.factors[k] ** e
        return N

    def __add__(self, o):
        o = self.lift(o)
        if self.zero:
            return o
        if o.zero:
            return self
        den = {k: max(self.den.get(k, 0), o.den.get(k, 0)) for k in set(self.den) | set(o.den)}
        shift = lambda x: {k: den[k] - x.den.get(k, 0) for k in den}
        return _Ref(self.times_factors(shift(self)) + o.times_factors(shift(o)), den, self.reg)

    __radd__ = __add__

    def __neg__(self):
        return _Ref(-self.N, self.den, self.reg, self.zero)

    def __sub__(self, o):
        return self + (-self.lift(o))

    def __rsub__(self, o):
        return self.lift(o) - self

    def __mul__(self, o):
        o = self.lift(o)
        if self.zero or o.zero:
            return self.reg.const(0)
        den = dict(self.den)
        for k, e in o.den.items():
            den[k] = den.get(k, 0) + e
        return _Ref(self.N * o.N, den, self.reg)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = self.lift(o)
        if self.zero:
            return self
        key = self.reg.new(o.N)          # (N/D) / (No/Do) = N Do / (D No)
        den = dict(self.den)
        den[key] = den.get(key, 0) + 1
        return _Ref(self.N * self.reg.one().times_factors(o.den), den, self.reg)

    def __rtruediv__(self, o):
        return self.lift(o) / self

    def value(self):
        return self.N.as_expr() / self.reg.one().times_factors(self.den).as_expr()


class _RefField:
    def __init__(self, gens):
        import sympy
        self.sympy, self.gens, self.factors, self.by_den = sympy, gens, {}, {}

    def poly(self, e):
        return self.sympy.Poly(e, *self.gens, domain="ZZ")

    def one(self):
        return _Ref(self.poly(1), {}, self)

    def new(self, F):
        k = len(self.factors)
        self.factors[k] = F
        return k

    def const(self, q):
        q = Fraction(q)
        if q == 0:
            return _Ref(self.poly(0), {}, self, zero=True)
        den = {}
        if q.denominator > 1:
            if q.denominator not in self.by_den:
                self.by_den[q.denominator] = self.new(self.poly(q.denominator))
            den = {self.by_den[q.denominator]: 1}
        return _Ref(self.poly(q.numerator), den, self)

    def param(self, i):
        return _Ref(self.poly(self.gens[i]), {}, self)

    def solve(self, M, B):
        sympy = self.sympy
        M = [[x if isinstance(x, _Ref) else self.const(x) for x in row] for row in M]
        B = [[x if isinstance(x, _Ref) else self.const(x) for x in row] for row in B]
        m = len(M)
        common = {}
        for row in M:
            for x in row:
                for k, e in x.den.items():
                    common[k] = max(common.get(k, 0), e)
        Mc = sympy.Matrix([[x.times_factors({k: common[k] - x.den.get(k, 0) for k in common}).as_expr()
                            for x in row] for row in M])
        det_key = self.new(self.poly(sympy.expand(Mc.det())))
        adj = Mc.adjugate()
        C = self.one().times_factors(common)
        out = []
        for i in range(m):
            row = []
            for j in range(len(B[0])):
                acc = self.const(0)
                for l in range(m):
                    acc = acc + B[l][j]
                if acc.zero:
                    row.append(acc)
                    continue
                total = self.poly(0)
                for l in range(m):
                    b = B[l][j]
                    if not b.zero:
                        total += self.poly(adj[i, l]) * b.times_factors(
                            {k: acc.den[k] - b.den.get(k, 0) for k in acc.den})
                den = dict(acc.den)
                den[det_key] = den.get(det_key, 0) + 1
                row.append(_Ref(C * total, den, self))
            out.append(row)
        return out


class _Pair:
    """A Deg marker and its reference numerator, computed in lockstep."""

    def __init__(self, d, r):
        self.d, self.r = d, r

    def _op(name):
        def op(self, o):
            if isinstance(o, _Pair):
                return _Pair(getattr(self.d, name)(o.d), getattr(self.r, name)(o.r))
            return _Pair(getattr(self.d, name)(o), getattr(self.r, name)(o))
        return op

    __add__, __radd__, __sub__, __rsub__ = _op("__add__"), _op("__radd__"), _op("__sub__"), _op("__rsub__")
    __mul__, __rmul__, __truediv__, __rtruediv__ = (_op("__mul__"), _op("__rmul__"), _op("__truediv__"),
                                                    _op("__rtruediv__"))

    def __neg__(self):
        return _Pair(-self.d, -self.r)


class _PairField:
    def __init__(self, nvars):
        import sympy
        self.gens = sympy.symbols(f"x0:{nvars}")
        self.D, self.R = DegreeField(), _RefField(self.gens)

    def const(self, q):
        return _Pair(self.D.const(q), self.R.const(q))

    def param(self, i):
        return _Pair(self.D.param(f"x{i}"), self.R.param(i))

    def solve(self, M, B):
        lift = lambda x: x if isinstance(x, _Pair) else self.const(x)
        M = [[lift(x) for x in row] for row in M]
        B = [[lift(x) for x in row] for row in B]
        Yd = self.D.solve([[x.d for x in row] for row in M], [[x.d for x in row] for row in B])
        Yr = self.R.solve([[x.r for x in row] for row in M], [[x.r for x in row] for row in B])
        return [[_Pair(a, b) for a, b in zip(ra, rb)] for ra, rb in zip(Yd, Yr)]


def _check_bounds(x, F):
    import math
    N = x.r.N
    if N.is_zero:
        return
    assert x.d.zero == x.r.zero and not x.d.zero
    assert N.total_degree() <= x.d.num
    l1 = sum(abs(int(c)) for c in N.coeffs())
    assert math.log2(l1) <= x.d.h + 1e-9
    for k, Fk in F.R.factors.items():      # the same factors, in the same order, on both sides
        if Fk.is_zero:
            continue
        assert Fk.total_degree() <= F.D.factor_degree[k]
        assert math.log2(sum(abs(int(c)) for c in Fk.coeffs())) <= F.D.factor_height[k] + 1e-9


def test_height_bound_dominates_the_numerator_of_a_fixed_program():
    import sympy
    F = _PairField(2)
    x, y = F.param(0), F.param(1)
    value = _poly_program(F, x * F.const(Fraction(3, 7)), y - F.const(Fraction(1000, 3)))
    _check_bounds(value, F)
    a, b = F.gens
    ref = _poly_program(_SympyField(), a * sympy.Rational(3, 7), b - sympy.Rational(1000, 3))
    assert sympy.cancel(value.r.value() - ref) == 0      # the reference numerator is the value's


class _SympyField:
    def solve(self, M, B):
        import sympy
        return sympy.Matrix(M).LUsolve(sympy.Matrix(B)).tolist()


@pytest.mark.parametrize("seed", range(12))
def test_height_bound_dominates_the_numerator_of_random_programs(seed):
    import sympy
    rng = random.Random(seed)
    F = _PairField(3)
    pool = [(F.param(i), F.gens[i]) for i in range(3)]
    for _ in range(2):
        q = Fraction(rng.randint(-10**6, 10**6), rng.randint(1, 999))
        pool.append((F.const(q), sympy.Rational(q.numerator, q.denominator)))
    for _ in range(10):
        (a, ea), (b, eb) = rng.choice(pool), rng.choice(pool)
        op = rng.choice("+-*/*")
        if op == "/" and b.r.N.is_zero:
            continue
        c, ec = {"+": lambda: (a + b, ea + eb), "-": lambda: (a - b, ea - eb), "*": lambda: (a * b, ea * eb),
                 "/": lambda: (a / b, ea / eb)}[op]()
        if rng.random() < 0.3:
            k = rng.choice([7, Fraction(-5, 11), 2**70])
            c, ec = c * k, ec * sympy.Rational(k.numerator, k.denominator)
        pool.append((c, ec))
        _check_bounds(c, F)
        assert sympy.cancel(c.r.value() - ec) == 0
    M = [[rng.choice(pool[3:])[0] for _ in range(2)] for _ in range(2)]
    B = [[rng.choice(pool)[0]] for _ in range(2)]
    if sympy.cancel(sympy.Matrix([[x.r.value() for x in row] for row in M]).det()) == 0:
        return
    Y = F.solve(M, B)
    expected = sympy.Matrix([[x.r.value() for x in row] for row in M]).LUsolve(
        sympy.Matrix([[x.r.value() for x in row] for row in B]))
    for i, row in enumerate(Y):
        for c in row:
            _check_bounds(c, F)
            assert sympy.cancel(c.r.value() - expected[i, 0]) == 0


def test_modular_constants_divisible_by_p_are_degenerate():
    from stiefelsym.backends.fields import ConstantDegenerate
    P = ModularField(101)
    for q in (101, -202, Fraction(3, 101), Fraction(101, 7)):
        with pytest.raises(ConstantDegenerate):
            P.const(q)
    assert P.const(0) == 0 and P.const(Fraction(3, 7)) * 7 == 3
