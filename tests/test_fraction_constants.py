"""Fraction constants next to a number of the scene are taken alike by every method (stop 89, h2 F1).

A whole-number Fraction (Fraction(2), Fraction(1, 3) * 3) times a trace, a number divided by a Fraction, λ times
a Fraction, and a resolvent at a Fraction were `error` (nmod or fmpq times a Fraction) under the point methods
while exact proved them; they are now the scene's own constants under every method, and their false twins are
refuted.
"""
from __future__ import annotations

from fractions import Fraction

import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one


def _t(s):
    return s.tr(s.P.T @ s.P)


def whole_fractions(s):
    t = _t(s)
    return {"Fraction(2) t - 2 t": Fraction(2) * t - 2 * t, "Fraction(1, 3) 3 t - t": Fraction(1, 3) * 3 * t - t,
            "t / Fraction(2) - t / 2": t / Fraction(2) - t / 2, "Fraction(-1) t + t": Fraction(-1) * t + t,
            "lambda Fraction(4) - 4 lambda": s.lam * Fraction(4) - 4 * s.lam}


def resolvent_at_fractions(s):
    return {"R(1/2) (I/2 - A) - I": s.resolvent(Fraction(1, 2)) @ (s.In / 2 - s.A) - s.In,
            "R(2) (2I - A) - I": s.resolvent(Fraction(2)) @ (s.In * 2 - s.A) - s.In}


def a_whole_fraction_too_many(s):
    """False: Fraction(3) t = t."""
    return {"Fraction(3) t - t": Fraction(3) * _t(s) - _t(s)}


def a_resolvent_at_the_wrong_fraction(s):
    """False: R(1/2) (I - A) = I."""
    return {"R(1/2) (I - A) - I": s.resolvent(Fraction(1, 2)) @ (s.In - s.A) - s.In}


METHODS = ["exact", "modular", "rational", "float", "ball", "free"]


@pytest.mark.parametrize("func", [whole_fractions, resolvent_at_fractions])
@pytest.mark.parametrize("method", METHODS)
def test_fraction_constants_are_taken_by_every_method(func, method):
    c = Claim(id="fractions", paper=("test",), kind="id", section="t", func=func, sizes=admissible(4))
    res = run_one(c, None if method == "free" else Size(3, 2), method, seed=0)
    assert res.verdict in ("proved", "checked", "numeric"), res.message


@pytest.mark.parametrize("func", [a_whole_fraction_too_many, a_resolvent_at_the_wrong_fraction])
@pytest.mark.parametrize("method", METHODS[:-1])
def test_their_false_twins_are_refuted(func, method):
    c = Claim(id="fractions-false", paper=("test",), kind="id", section="t", func=func, sizes=admissible(4))
    assert run_one(c, Size(3, 2), method, seed=0).verdict == "fails"


def a_huge_whole_fraction_off_by_t(s):
    """False (P ≠ 0): Fraction(10**400) t − 10**400 t + t = 0; a whole Fraction far beyond float64 is an int too."""
    t = _t(s)
    return {"r": Fraction(10**400) * t - 10**400 * t + t}


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float"])
def test_a_huge_whole_fraction_does_not_hide_a_term(method):
    c = Claim(id="fractions-huge", paper=("test",), kind="id", section="t", func=a_huge_whole_fraction_off_by_t,
              sizes=admissible(4))
    assert run_one(c, Size(3, 2), method, seed=0).verdict == "fails"
    assert run_one(c, None, "free", seed=0).verdict == "undecided"
