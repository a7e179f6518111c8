"""Stop 80's replays: the one-function rule held when the claim's trace ends, by shape or by substitution (true
claims whose call passes a node the function itself computes were refused: stop 79's second review, R1), a
function a step shapes like its argument held across steps (a stateful kinetic energy in two euler_lagrange
calls, W3b), the Dirac bracket of no constraint (R2), and the stop's own attempt on its change."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ADVERSARY = Path(__file__).parent
REVIEW2 = ADVERSARY / "s79" / "review2"
OWN = ADVERSARY / "s80" / "own"

ONE_FUNCTION = "a statement about one function"
USED_AGAIN = "traces to another graph when it is used again"
TRUE = ("proved", "checked", "numeric")


def _records(path: Path, *args: str) -> dict:
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(path), "--jobs", "1",
                          "--format", "json", *args], capture_output=True, text=True, timeout=600)
    assert out.stdout.strip(), out.stderr[-2000:]
    return {(r["claim"], r.get("n"), r.get("r")): r for r in json.loads(out.stdout)["results"]}


def _decided(rec: dict, true: bool, method: str) -> None:
    want = TRUE if true else (("undecided",) if method == "free" else ("fails",))
    assert rec["verdict"] in want, (rec["claim"], rec.get("n"), rec.get("r"), method, rec["verdict"],
                                    rec.get("message", "")[:300])


@pytest.mark.parametrize("method", ["exact", "modular", "free"])
def test_a_call_whose_argument_is_a_node_the_function_computes(method):
    """Stop 79's second review, R1: the graph shares equal nodes, so Λ(a·b; a, b) of the Lie–Poisson form (which
    computes a·b itself), the paper's Λ2 at the covector A (whose form reads A) and quadratic's u ↦ Mu + uM at
    u = M read as another graph of their arguments than the reference's, and these true claims were refused
    under every method.  A call now also holds when the reference's graph, the call's scene and arguments put in
    place of the reference's, is the call's node; the false twins stay false."""
    for name in ("subexpr_refusal.py", "lambda2_at_A.py", "quad_subexpr.py"):
        for (cid, _n, _r), rec in _records(REVIEW2 / name, "--method", method).items():
            _decided(rec, not cid.endswith("-false"), method)


@pytest.mark.parametrize("method", ["exact", "modular", "free"])
def test_a_stateful_kinetic_energy_in_two_euler_lagrange_calls(method):
    """Stop 79's second review, W3b: a kinetic energy c·tr(ẊᵀẎ) whose c the claim flips between two
    euler_lagrange calls of one system was two Lagrangians, and "the accelerations are those of c = 1 and those of
    c = 2" was proved (free: for all n, r).  A function a step shapes like its argument is now held, at a use
    with an argument of the same shape, to the graph of its first; the control (two objects) stays true."""
    for (cid, _n, _r), rec in _records(REVIEW2 / "el_stateful.py", "--method", method).items():
        if cid.endswith("-contradiction"):
            assert rec["verdict"] == "error" and USED_AGAIN in rec["message"], (cid, method, rec["verdict"])
        else:
            _decided(rec, True, method)


@pytest.mark.parametrize("method", ["exact", "modular"])
def test_the_dirac_bracket_of_no_constraint_is_the_canonical_one(method):
    """Stop 79's second review, R2: dirac_bracket_for of an empty list (or of 0×0 matrices) inverted a 0×0
    matrix and gave an error; it is the canonical bracket."""
    for (cid, _n, _r), rec in _records(REVIEW2 / "dirac_shapes.py", "--method", method).items():
        _decided(rec, not cid.endswith("-false"), method)


@pytest.mark.parametrize("method", ["exact", "modular", "float", "free"])
def test_a_reference_whose_argument_the_function_computes_cannot_vouch_for_two_functions(method):
    """The stop's own attempt on its change: a form that is <x, x − q·p> at the claim's point y and the
    Lie–Poisson form elsewhere, called first at (a·b; a, b), where both branches are one node.  That call's
    graph, read by shape, has the first branch's form, and by substitution the second's: the two statements
    about T(y; a, b) and T(z; c, d) contradict each other, and the claim is refused whether or not a
    checked_tensor step's function is there too.  The engine's lie_poisson at the same calls is true."""
    for (cid, _n, _r), rec in _records(OWN / "conflated_reference.py", "--method", method).items():
        if "conflated" in cid:
            assert rec["verdict"] == "error" and ONE_FUNCTION in rec["message"], (cid, method, rec["verdict"])
        else:
            _decided(rec, True, method)


@pytest.mark.parametrize("method", ["exact", "modular", "float", "free"])
def test_poisson_checks_of_a_form_that_is_no_bivector(method):
    """The stop's own attempt: <x, [a, b]> + tr(a)tr(b)(tr a − tr b) is antisymmetric, of degree 1 in x, and
    its jacobiator of linear functions is 0, but it is not bilinear: poisson_checks proved it Poisson (free for
    all n, r).  poisson_checks now checks additivity in a covector as well."""
    for (cid, _n, _r), rec in _records(OWN / "nonbilinear.py", "--method", method).items():
        _decided(rec, cid != "nonbilinear-poisson", method)
        if cid == "nonbilinear-poisson" and method != "free":
            assert (rec.get("witness") or {}).get("check", "").startswith("Λ(a + c, b)"), rec
