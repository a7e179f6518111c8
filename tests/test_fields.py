"""Fields: exactness, degree bounds, dual numbers and the float error model."""
import random
from fractions import Fraction

import pytest

from stiefelsym.fields import (DegenerateError, Deg, DegreeField, Dual, FloatField, ModularField,
                               RationalField, SymbolicField)
from stiefelsym.matrix import Mat


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
