"""Numbers of a field built over another's (dual, reverse and degree-paired numbers in a tower): a value of a
lower layer is a constant of the higher one, whichever operand comes first (round 10, IB: a value a function
captured from the claim's scene, met inside a bracket taken inside a function whose gradient is taken)."""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from stiefelsym.backends.fields import Dual, DualField, RationalField, tower_level
from stiefelsym.backends.matrix import Mat
from stiefelsym.backends.paired import PairField
from stiefelsym.backends.reverse import Rev, RevField


def _pair(field, q):
    return field.const(Fraction(q))


def test_a_lower_number_is_a_constant_of_the_higher_one_whichever_comes_first():
    P = PairField(RationalField())
    c, x, y = _pair(P, 3), _pair(P, 5), _pair(P, 7)
    d = Dual(x, y)                       # 5 + 7ε over the paired field
    for got in (c * d, d * c):
        assert type(got) is Dual and got.a.v == 15 and got.b.v == 21
    for got in (c + d, d + c):
        assert type(got) is Dual and got.a.v == 8 and got.b.v == 7
    assert (c - d).a.v == -2 and (c - d).b.v == -7 and (d - c).a.v == 2
    assert str((c / d).a.v) == "3/5" and str((c / d).b.v) == "-21/25"
    r = Rev(d)                           # a reverse number over the dual numbers
    assert tower_level(c) == 1 and tower_level(d) == 2 and tower_level(r) == 3
    for got in (c * r, r * c, d * r, r * d):
        assert type(got) is Rev and type(got.v) is Dual
    assert (d * r).v.a.v == 25 and (d * r).v.b.v == 70
    assert (c * r).v.a.v == 15 and (c * r).v.b.v == 21


def test_dual_numbers_of_two_layers_are_not_taken_for_one():
    """ε₁ of an outer derivative is a constant of the inner dual numbers (ε₂), not ε₂."""
    F = RationalField()
    outer = Dual(F.const(2), F.const(1))                        # 2 + ε₁
    inner = Dual(Dual(F.const(3), F.const(0)), Dual(F.const(1), F.const(0)))   # 3 + ε₂
    for got in (outer * inner, inner * outer):
        # (2 + ε₁)(3 + ε₂) = (6 + 3ε₁) + (2 + ε₁)ε₂
        assert (got.a.a, got.a.b, got.b.a, got.b.b) == (6, 3, 2, 1)


def test_a_matrix_of_a_lower_field_is_lifted_to_the_higher_one():
    P = PairField(RationalField())
    D = DualField(P)
    R = RevField(D)
    low = Mat.from_rows([[_pair(P, 1), _pair(P, 2)]], P)
    high = Mat.from_rows([[R.lift(D.lift(_pair(P, 3)))], [R.lift(D.lift(_pair(P, 4)))]], R)
    for got in (low @ high, (high.T @ low.T).T):
        assert got._field is R
        v = got._view()[0, 0]
        assert type(v) is Rev and v.v.a.v == 11
    s = low.T + high
    assert s._field is R and np.all([type(v) is Rev for v in s._view().flat])


def test_reverse_numbers_of_two_layers_are_not_taken_for_one():
    F = RationalField()
    low = Rev(F.const(2))
    high = Rev(Rev(F.const(3)))
    for got in (low * high, high * low, low + high, high - low, low - high, high / low, low / high):
        assert type(got) is Rev and type(got.v) is Rev
    assert (low * high).v.v == 6 and (low - high).v.v == -1 and str((low / high).v.v) == "2/3"


def test_a_dual_number_of_plain_numbers_fits_any_layer():
    P = PairField(RationalField())
    x = Dual(_pair(P, 2), _pair(P, 3))
    for got in (x + Dual(0, 0), Dual(0, 0) + x, x * Dual(1, 0)):
        assert type(got) is Dual and type(got.a) is not Dual and tower_level(got) == 2
