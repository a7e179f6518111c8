"""Stop 93's replays.

- Stop 92's h2 M1: under ``free``, a nonvanishing statement whose trace is refused was ``undecided`` ("rewriting proves
  vanishing only"), where every fixed-size method says ``error``: the method showed through the outcome.  It is
  ``error`` under free too, with the refusal.
- Stop 92's h2 M2: a check with no entries (a 0×0 block) was ``inconclusive`` under ball ("no residuals to
  enclose") and ``error`` elsewhere.  Ball now refuses it with the message of the others.
"""
from __future__ import annotations

from pathlib import Path

import stiefelsym

OWN = Path(__file__).parent / "s93" / "own"
FIXED = ["exact", "modular", "rational", "float", "ball"]


def test_a_refused_or_vacuous_claim_has_one_outcome_whatever_the_method():
    res = stiefelsym.verify(["own-refused-nonzero", "own-refused-zero", "own-empty-check", "own-empty-beside-false"],
                            files=[OWN / "same_outcome.py"], sizes=[(3, 2)], methods=FIXED + ["free"], jobs=1)
    by = {(r.claim, r.method): r for r in res}
    for cid in ("own-refused-nonzero", "own-refused-zero"):
        for m in FIXED + ["free"]:
            r = by[(cid, m)]
            assert r.verdict == "error" and "spaces do not match" in r.message, (cid, m, r.verdict, r.message)
    for cid in ("own-empty-check", "own-empty-beside-false"):
        for m in FIXED:
            r = by[(cid, m)]
            assert r.verdict == "error" and "has no entries" in r.message, (cid, m, r.verdict, r.message)
        # a block is an entry read: the dimension-free scene leaves it to the fixed sizes (never a verdict)
        assert by[(cid, "free")].verdict == "undecided"


def test_a_refusal_a_traced_function_raises_itself_is_named_as_such():
    """Stop 92 left it: a function handed to ``s.d`` that raised the engine's own TraceRefused (caught by the claim)
    gave ``error`` saying the claim had changed the graph.  It is now recorded as what it is."""
    fool = Path(__file__).parent / "s92" / "own" / "fool.py"
    res = stiefelsym.verify(["own-spoofed-refusal-false"], files=[fool], sizes=[(3, 2)], methods=FIXED + ["free"],
                            jobs=1)
    for r in res:
        assert r.verdict == "error", (r.method, r.verdict)
        assert "a function handed to the engine raised TraceRefused" in r.message, (r.method, r.message)


def test_an_operand_is_a_traced_value_an_int_a_fraction_or_a_size_and_nothing_else():
    """The operands of +, −, ·, / are an allow-list: a scene, an engine constant (an operator space), a float, a
    complex number are refused when the claim is traced, whatever the method."""
    import pytest

    from stiefelsym.ir import compile_claim
    from stiefelsym.ir.trace import TraceRefused
    from stiefelsym.scene import REALIZATIONS
    cons = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)

    def scene_operand(s):
        return {"r": s.P - s.P * s}

    def complex_operand(s):
        return {"r": s.P - s.P * 1j}
    for f, words in ((scene_operand, "a TraceScene is not a number of the IR"),
                     (complex_operand, "a complex is not a value of the IR")):
        with pytest.raises(TraceRefused, match=words):
            compile_claim(f, 3, 2, cons)


def test_the_options_of_a_claim_and_of_verify_are_checked_with_the_argument_named():
    """Stop 93's h2 I3, I4, I5: ``@claim(exact_max_n="5")``, ``realization="bogus"``, ``paper=5`` and
    ``statement=None`` gave raw Python errors (or an ``error`` at every run); ``verify(sizes=[])`` and
    ``verify(methods=[])`` returned nothing with ``ok == True``; ``seed=1.5``, ``jobs=1.5`` and ``budget=nan`` were
    accepted.  Each is a ValueError that names the option."""
    import math

    import pytest

    from stiefelsym import claim
    from stiefelsym.claims import REALIZATION_NAMES
    from stiefelsym.scene import REALIZATIONS
    assert tuple(REALIZATIONS) == REALIZATION_NAMES

    def body(s):
        return {"r": s.X.T @ s.X - s.Ir}
    for options, words in (({"exact_max_n": "5"}, "exact_max_n"), ({"exact_max_n": math.nan}, "exact_max_n"),
                           ({"realization": "bogus"}, "realization"), ({"paper": 5}, "paper"),
                           ({"statement": None}, "statement")):
        with pytest.raises(ValueError, match=words):
            claim("own-options", kind="id", sizes=[(2, 1)], **options)(body)
    for kwargs, words in (({"sizes": []}, "sizes"), ({"methods": []}, "methods"), ({"seed": 1.5}, "seed"),
                          ({"seed": "random"}, "seed"), ({"jobs": 1.5}, "jobs"), ({"budget": math.nan}, "budget"),
                          ({"timeout": "5"}, "timeout"), ({"memory": 0}, "memory")):
        with pytest.raises(ValueError, match=words):
            stiefelsym.verify(["neumann-lax"], **kwargs)


def test_a_size_text_is_read_one_way_by_the_command_line_the_library_and_the_pytest_plugin():
    """Stop 93's h2 I1: "4,+2" was (4, 2) for --size, a ValueError for ``verify(sizes=["4,+2"])``, and an item (4,2)
    of the pytest plugin whose file was never traced there.  One reader (stiefelsym.sizerules.parse_size) serves
    them all, with one message for a text that is no size."""
    import pytest

    from stiefelsym.api import _size_text
    from stiefelsym.sizerules import parse_size
    assert parse_size("4,+2") == parse_size(" n = 4 , r = 2 ") == _size_text("4,+2") == (4, 2)
    for bad, words in (("4", "is not a size"), ("2,3", "needs r <= n"), ("0,0", "needs n >= 1"),
                       ("3,-1", "needs r >= 1")):
        with pytest.raises(ValueError, match=words):
            parse_size(bad)


def test_a_residual_below_float64s_range_is_refuted_by_ball_and_printed_as_it_is():
    """Stop 93's h2 I6 and M1: (tr XᵀX − r − 1)·2⁻²⁰⁰⁰ printed "max |residual| 0.00e+00" beside "exceeds its error
    bound" (the mpmath magnitudes went through float64), and ball could not refute it (an enclosure excluded 0 only
    where the float64 of its lower end was positive).  Ball now decides exclusion in arb; the texts print the
    magnitudes beyond float64's range."""
    h2 = Path(__file__).parent / "s93" / "h2" / "k_api.py"
    res = stiefelsym.verify(["k-pow-false", "k-pow"], files=[h2], sizes=[(3, 2)], methods=["ball", "float"], jobs=1)
    by = {(r.claim, r.method): r for r in res}
    assert by[("k-pow-false", "ball")].verdict == by[("k-pow-false", "float")].verdict == "fails"
    assert by[("k-pow", "float")].verdict == "numeric" and "e-6" in by[("k-pow", "float")].certificate
    assert by[("k-pow", "ball")].verdict != "fails"
    assert "mpmath30: max |residual| 0.00e+00" not in by[("k-pow-false", "float")].message


def test_a_tiny_or_cancelled_residual_fools_no_method():
    """The review's own trick on the stop's change to ball (exclusion of 0 decided in arb): false statements whose
    residual is 2⁻¹¹⁰⁰ (below float64's normal range) and a nonvanishing one that is 0 on T*V, beside true twins
    (a 10³⁰⁰ cancellation, a nonvanishing 2⁻¹¹⁰⁰·XᵀX).  No method passes a false one; ball may stay inconclusive on
    the cancellation, never refute it."""
    res = stiefelsym.verify(None, files=[OWN / "tiny.py"], sizes=[(3, 2)], methods=FIXED + ["free"], jobs=1)
    by = {(r.claim, r.method): r.verdict for r in res}
    for m in FIXED + ["free"]:
        for cid in ("fool-subnormal-false", "fool-nonzero-false"):
            assert by[(cid, m)] not in ("proved", "checked", "numeric"), (cid, m, by[(cid, m)])
        assert by[("fool-cancel-true", m)] != "fails" and by[("fool-nonzero-true", m)] != "fails", m
    assert by[("fool-subnormal-false", "ball")] == by[("fool-nonzero-false", "ball")] == "fails"
