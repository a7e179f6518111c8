"""Stop 92's replays: an adversary on the eight routes of the claims file (h2: tests/adversary/s92/h2), its usability
findings kept as tests (no wrong verdict was found).

- I1: a str, None, a list, a tuple or a dict was accepted as an operand of +, −, ·, /, as an entry of ``s.mat``, as
  the spectral parameter of ``s.resolvent`` or the number of ``s.scalar_matrix``; each method then failed with its
  own backend's TypeError (the method showed through the message), and free said ``undecided``.  They are refused
  when the claim is traced, with one message, whatever the method.
- I2: a function handed to ``s.d`` or ``s.bracket`` raised and the claim caught it: every method answered ``error``
  saying claim code had changed the graph.  The refusal now says what happened.
"""
from __future__ import annotations

from pathlib import Path

import pytest

import stiefelsym

HERE = Path(__file__).parent / "s92" / "h2"
METHODS = ["exact", "modular", "rational", "float", "free"]


def _run(file: str, ids: list[str]):
    return stiefelsym.verify(ids, files=[HERE / file], sizes=[(3, 2)], methods=METHODS, jobs=1)


@pytest.mark.parametrize("file, ids", [
    ("c2_str.py", ["c2-str-sub", "c2-str-lam", "c2-str-zero", "c2-str-mat"]),
    ("c2_str2.py", ["c2s-mat1", "c2s-mat0", "c2s-res"]),
])
def test_a_non_number_operand_is_refused_when_traced_with_one_message(file, ids):
    res = _run(file, ids)
    assert {r.verdict for r in res} == {"error"}, [(r.claim, r.method, r.verdict) for r in res]
    for r in res:
        assert "is not a number of the IR (exact constants are int and Fraction)" in r.message, (r.method, r.message)


def test_a_caught_exception_of_a_traced_function_is_named():
    res = _run("c3_control.py", ["c3-raise-no-nodes", "c3-bracket-control"])
    by = {(r.claim, r.method): r for r in res}
    for m in METHODS:
        r = by[("c3-raise-no-nodes", m)]
        assert r.verdict == "error" and "a function handed to the engine raised RuntimeError" in r.message, r.message
        assert by[("c3-bracket-control", m)].verdict in ("proved", "checked", "numeric"), m


# -- the review's own tricks (tests/adversary/s92/own) ------------------------------------------------------------

OWN = Path(__file__).parent / "s92" / "own"


def test_a_spoofed_refusal_or_a_caught_str_operand_never_gives_a_verdict():
    """A traced function that raises the engine's own TraceRefused (caught by the claim), and a str operand whose
    refusal is caught with a 0 put in its place: both are ``error`` under every method, never a verdict on the false
    statement that follows."""
    res = stiefelsym.verify(["own-spoofed-refusal-false", "own-refusal-then-number"], files=[OWN / "fool.py"],
                            sizes=[(3, 2)], methods=METHODS, jobs=1)
    assert {r.verdict for r in res} == {"error"}, [(r.claim, r.method, r.verdict) for r in res]


def test_the_family_proof_at_r_4_does_not_prove_a_corrupted_invariance():
    """Negative control of the proof on the family r = 4 (free_max_r = 4, as 2r-integrals-conserved): the
    coefficients e_2l(L*(λ)) moved along P ↦ P + εAX, which changes them off r = n (truth_family4.py, numpy).  The
    run at (5,4) fails with a witness, and is proved by no method; at (4,4), r = n, the statement holds."""
    res = stiefelsym.verify(["own-family4-false"], files=[OWN / "family4.py"], jobs=1)
    by = {(r.n, r.r): r for r in res}
    assert by[(5, 4)].verdict == "fails" and by[(5, 4)].witness, by[(5, 4)].message
    assert by[(4, 4)].verdict in ("proved", "checked"), by[(4, 4)].message
