"""Replaying a float evaluation in ℚ: the same parameters, read exactly, so that every float
entry can be compared with the exact value at the same point (|computed − exact| <= its bound)."""

from __future__ import annotations

from fractions import Fraction

import flint

from stiefelsym.backends.fields import RationalField


def entries(M):
    return [[M._view()[i, j] for j in range(M._shape()[1])] for i in range(M._shape()[0])]


def exact_of(x) -> flint.fmpq:
    """A float number's value, exactly."""
    return flint.fmpq(*Fraction(x.v).as_integer_ratio())


def replay_field(F) -> RationalField:
    """A rational field whose parameters are those the float field F draws, read exactly."""

    class Replay(RationalField):
        def param(self, name, rng):
            return exact_of(F.param(name, rng))
    return Replay()


def assert_within_bounds(out, exact, scales: bool = False) -> None:
    """Every entry of the float matrices ``out`` is within its error bound of the exact one (and,
    with ``scales``, its term scale is at least its size, to a few digits)."""
    for M, Mq in zip(out, exact):
        for row, rowq in zip(entries(M), entries(Mq)):
            for x, q in zip(row, rowq):
                assert abs(Fraction(x.v) - Fraction(int(q.p), int(q.q))) <= Fraction(x.e)
                if scales:
                    assert x.m >= abs(x.v) * (1 - 1e-4)
