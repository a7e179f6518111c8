"""Round 4b: the `Inverse` statement (an operator invertible at every point of T*V, with its inverse) and
the exact confirmation of a `numeric` verdict at one point mod p per component.  As in the earlier rounds
every run is the CLI in a fresh process, each test asserts the CORRECT outcome, and a route that is open
today is a strict xfail with its reason."""

import copy
import json

from adversary_cli import HERE, PASSING, cli
from test_adversary_s33 import ALL_METHODS, parse_all

FIXED = ALL_METHODS


def run_all(claims_file, ids=(), size="3,2", methods=ALL_METHODS, free=True, extra=()):
    """{(claim, method): verdict} of one run of the fixed-size methods at one size (and one of free), one
    worker each."""
    args = ["verify", *ids, "--claims", str(HERE / claims_file), "--size", size, "--jobs", "1", *extra]
    for m in methods:
        args += ["--method", m]
    got = parse_all(cli(*args).stdout)
    if free:
        got.update(parse_all(cli("verify", *ids, "--claims", str(HERE / claims_file), "--method", "free",
                                 "--jobs", "1").stdout))
    return got


def by_claim(got):
    """{claim: {method: verdict}} of run_all's {(claim, method): verdict} (auto's line names the method it
    chose, so a method may hold two runs: its verdicts are the set of both)."""
    out: dict = {}
    for (c, m), v in got.items():
        out.setdefault(c, {})[m] = v
    return out


def fixed(verdicts):
    """The verdicts of the fixed-size methods of one claim."""
    return {v for m, v in verdicts.items() if m != "free"}


# -- 4b-A. an inverse that divides by something vanishing somewhere ---------------------------------------

DIVISIONS = ("adv-s34b-inv-div-trace", "adv-s34b-inv-div-sphere", "adv-s34b-inv-pow", "adv-s34b-inv-congruence-ptp",
             "adv-s34b-inv-congruence-xax", "adv-s34b-inv-element-inverse", "adv-s34b-inv-element-sphere")


def test_an_inverse_with_a_vanishing_divisor_is_never_passed():
    """op(inv(y)) = y and inv(op(x)) = x hold as rational functions, which proves op invertible only where
    the divisors (tr PᵀP, tr PᵀP − 1, (PᵀP)⁻¹, (XᵀAX)⁻¹, x⁻¹, 1/tr(xxᵀ)) do not vanish: every fixed-size
    method said proved / checked / numeric before.  Closed: a divisor in op or inv that is not a constant is
    refused when the statement is made (error at fixed sizes, undecided by free)."""
    got = by_claim(run_all("s34b_inverse_divisions.py"))
    assert set(got) == set(DIVISIONS), got
    for c, verdicts in got.items():
        assert len(verdicts) >= len(FIXED), (c, verdicts)
        assert not set(verdicts.values()) & set(PASSING), (c, verdicts)
        assert fixed(verdicts) == {"error"} and verdicts["free"] == "error", (c, verdicts)


def test_an_op_that_leaves_the_shape_of_its_space_is_never_passed():
    """xᵀ on R^{n×r} (and a swapped pair of transposes) is its own inverse, but maps R^{n×r} to R^{r×n}: no
    membership residual is made for a general space, so exact, modular, float, ball and free passed it.
    Closed: op(x) and inv(y) must have the shape of their space (refused otherwise)."""
    got = by_claim(run_all("s34b_inverse_spaces.py"))
    for c, verdicts in got.items():
        assert len(verdicts) >= len(FIXED), (c, verdicts)
        assert not set(verdicts.values()) & set(PASSING), (c, verdicts)


def test_resolvents_hidden_divisions_and_maps_that_are_not_linear():
    """A resolvent at μ = tr PᵀP, a division inside a function the engine differentiates (s.d, a Dirac
    flow's Hamiltonian): passed before, now refused.  A map that is not injective and an inverse valid at
    r = 1 only fail at (3,2) and are undecided by free; a true triangular map that is not linear is
    passed by every method."""
    got = by_claim(run_all("s34b_inverse_probes.py"))
    for c in ("adv-s34b-inv-resolvent", "adv-s34b-inv-hidden-quotient", "adv-s34b-inv-hidden-flow"):
        assert fixed(got[c]) == {"error"} and got[c]["free"] == "undecided", (c, got[c])
    for c in ("adv-s34b-inv-not-linear", "adv-s34b-inv-r1-only"):
        assert fixed(got[c]) == {"fails"} and got[c]["free"] == "undecided", (c, got[c])
    true = got["adv-s34b-inv-triangular-true"]
    assert true["exact"] == "proved" and true["free"] == "proved", true
    assert true["modular"] == true["rational"] == "checked" and true["float"] == true["ball"] == "numeric", true


def test_a_division_inside_an_engine_step_is_never_passed():
    """The multipliers of `systems.hamiltonian_flow` with the claim's own constraints F₁ = tr(XᵀP),
    F₂ = tr(PᵀP)/2 solve {F_i, F_j} μ = b, and {F₁, F₂} = tr(PᵀP) vanishes at P = 0: x ↦ μ₂x with a
    polynomial inverse tr(PᵀP)y/2 was proved / checked / numeric (the engine step is one opaque node).
    Closed: an engine step that solves a system built from the claim's own functions or matrices
    (hamiltonian_flow, euler_lagrange, the twisted bracket, flow, multiplier flow, at_point) is refused
    inside op and inv."""
    got = by_claim(run_all("s34b_inverse_engine_division.py", size="3,2"))
    assert len(got) == 2, got
    for c, verdicts in got.items():
        assert fixed(verdicts) == {"error"} and verdicts["free"] == "error", (c, verdicts)


# -- 4b-B. the exact confirmation of a float / ball `numeric` ---------------------------------------------

def test_a_residual_on_one_component_of_o_n_is_refuted_by_the_confirmation():
    """det X = 1 and X_11 = its cofactor, hidden from float64 by an absorption (cu + R) − cu: true on SO(n)
    only.  The confirmation evaluates one point mod p on each component of O(n) (r = n) and refutes
    them (no hole found)."""
    for ids, size in ((("adv-s34b-comp-det2",), "2,2"), (("adv-s34b-comp-cofactor",), "3,3")):
        got = by_claim(run_all("s34b_confirm_component.py", ids=ids, size=size, methods=("float", "ball", "auto"),
                               free=False))
        for c, verdicts in got.items():
            assert fixed(verdicts) == {"fails"}, (c, size, verdicts)


def test_hard_cases_do_not_confirm_a_false_numeric():
    """Under --hard the confirmation is at the hard case's chosen exact point, where vanishing is no
    evidence: a residual that vanishes exactly at the near-pole λ, and a "nonzero" residual float64 sees
    only through an absorption, are not passed by float or ball (no hole found: float cannot resolve λ
    next to the pole, ball's dyadic point is not the hard point, and a vanishing hard point leaves a
    "nonzero" claim inconclusive)."""
    for hard in ("near-pole", "near-pole-1e-8", "far-chart"):
        got = by_claim(run_all("s34b_confirm_hard.py", methods=("float", "ball"), free=False,
                               extra=("--hard", hard)))
        assert len(got) == 4, (hard, got)
        for c, verdicts in got.items():
            assert not set(verdicts.values()) & set(PASSING), (hard, c, verdicts)


def test_a_certificate_moved_to_a_false_inverse_is_rejected(tmp_path):
    """The free record of a true Inverse statement (the triangular map) grafted onto the false one (an
    inverse valid at r = 1 only), verdict `proved`: `check` runs the free method again and rejects it
    (no hole found)."""
    out = tmp_path / "run"
    ids = ("adv-s34b-inv-triangular-true", "adv-s34b-inv-r1-only")
    cli("verify", *ids, "--claims", str(HERE / "s34b_inverse_probes.py"), "--method", "free", "--jobs", "1",
        "--report-dir", str(out))
    payload = json.loads((out / "results.json").read_text())
    records = {r["claim"]: r for r in payload["results"]}
    assert records[ids[0]]["verdict"] == "proved" and records[ids[1]]["verdict"] == "undecided", records
    true = records[ids[0]]
    for key in ("verdict", "reductions", "certificate", "checks", "certificate_data", "message", "seconds"):
        records[ids[1]][key] = copy.deepcopy(true[key])
    forged = tmp_path / "forged.json"
    forged.write_text(json.dumps(payload))
    res = cli("check", str(forged))
    assert res.returncode == 1 and f"REJECTED {ids[1]}" in res.stdout and "re-derived" in res.stdout, (
        res.returncode, res.stdout[-2000:])
