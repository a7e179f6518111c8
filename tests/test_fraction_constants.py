"""A Fraction constant next to a number of the scene (λ − 1/8): every method converts it to its own field
(nmod, fmpq, a symbol, an enclosure, a free coefficient), so a true claim is passed and a false one fails,
where before each backend raised TypeError and every verdict was `error`."""
from __future__ import annotations

from fractions import Fraction

import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one

EIGHTH = Fraction(1, 8)


def _true(s):
    return {"r": (s.lam - EIGHTH) * s.X - s.lam * s.X + EIGHTH * s.X,
            "l": (EIGHTH - s.lam) * s.X + s.lam * s.X - EIGHTH * s.X,
            "t": s.tr(s.X.T @ s.X) * EIGHTH - s.tr(s.Ir) * EIGHTH,
            "u": (s.lam / Fraction(3, 2) - s.lam * Fraction(2, 3)) * s.X}


def _false(s):
    return {"r": (s.lam - EIGHTH) * s.X - s.lam * s.X}


TRUE = Claim(id="fraction-true", paper=("LA1",), kind="id", section="5", func=_true, sizes=admissible(4))
FALSE = Claim(id="fraction-false", paper=("LA1",), kind="id", section="5", func=_false, sizes=admissible(4))
PASS = {"proved", "checked", "numeric"}


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float", "ball", "free"])
def test_fraction_next_to_a_scalar(method):
    size = None if method == "free" else Size(3, 2)
    good, bad = run_one(TRUE, size, method, seed=3), run_one(FALSE, size, method, seed=3)
    assert good.verdict in PASS, (method, good.verdict, good.message)
    assert bad.verdict == ("undecided" if method == "free" else "fails"), (method, bad.verdict, bad.message)
