"""A registered correction may change what the statement asserts: a printed "does not hold"
that does hold is corrected to "holds", and verified as such."""
from __future__ import annotations

import pytest

from stiefelsym import admissible, comm
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import verify


def _registered(func, expect):
    c = Claim(id="says-it-fails", paper=("prep",), kind="not", section="t", func=func,
              sizes=admissible(3, n_min=3, r_min=2, r_max=2), expect=expect, erratum="it holds")
    return c


def phi_commutes_with_itself(s):
    """[Φ, Φ] = 0, printed as "does not vanish"."""
    return {"[Phi, Phi]": comm(s.Phi, s.Phi)}


def test_a_correction_to_holds_is_verified_as_holding():
    c = _registered(phi_commutes_with_itself, "nonzero")
    c.correction("it holds", expect="holds")(phi_commutes_with_itself)
    results = verify([c], methods=("modular",), sizes=[Size(3, 2)], jobs=1, fork=False)
    printed = [r for r in results if r.variant is None]
    corrected = [r for r in results if r.variant == "it holds"]
    assert printed and printed[0].verdict == "fails"
    assert corrected and corrected[0].verdict == "checked" and corrected[0].expected


def test_a_correction_expects_holds_or_nonzero():
    c = _registered(phi_commutes_with_itself, "nonzero")
    with pytest.raises(ValueError):
        c.correction("unclear", expect="maybe")
