"""Routes by which a claims file obtains a wrong verdict (adversarial review).  Each test asserts the
CORRECT outcome; each fails today, hence ``xfail(strict=True)``: when a route is closed its test
passes and the strict xfail turns red, to be unmarked.  Every run is a fresh process (the routes
change process-wide state: primitives, backends, the graph cache)."""
import json
import subprocess
import sys

import pytest

#: the exact variant of a test whose exact run takes the longest (its symbolic attempt at (3,2) runs to its
#: budget or its end): run with the tests marked slow (`make verify-all`); the other methods run by default
EXACT_SLOW = pytest.param("exact", marks=pytest.mark.slow)
FLOAT_SLOW = pytest.param("float", marks=pytest.mark.slow)

from adversary_cli import HERE, LINE, PASSING, ROOT, cli, parse, run_verify, verdicts_each  # noqa: E402,F401


def verdicts(claims_file, method, size="3,2", ids=()):
    """{claim id: verdict} of one `stiefelsym verify` run; a file the engine refused when it was loaded
    has no verdict at all, for any of its claims."""
    run = run_verify(claims_file, method, size, ids)
    if run.returncode == 2 and ("registered by the engine" in run.stderr or "engine was changed" in run.stderr):
        return {cid: "refused" for cid in ids} | {"*": "refused"}
    return parse(run.stdout)


def _v(claims_file, method, cid, size="3,2", ids=()):
    v = verdicts(claims_file, method, size, ids)
    if v.get("*") == "refused":
        return "refused"
    assert cid in v, v
    return v[cid]


def _v_each(claims_file, methods, cid, size="3,2", ids=()):
    """{method: verdict of ``cid``} (:func:`verdicts_each`)."""
    out = {}
    for method, v in verdicts_each(claims_file, methods, size, ids).items():
        assert v.get("*") == "refused" or cid in v, (method, v)
        out[method] = "refused" if v.get("*") == "refused" else v[cid]
    return out


def none_passes(verdicts_by_method):
    return not set(verdicts_by_method.values()) & set(PASSING)


# -- A. the dimension-free proof compares only two fixed sizes -----------------------------------

def test_size_branch_is_not_proved_for_all_sizes():
    assert _v("size_branch_free.py", "free", "adv-size-branch") not in PASSING


def test_size_branch_beyond_the_listed_sizes_is_not_proved():
    assert _v("size_branch_beyond.py", "free", "adv-size-branch-beyond") not in PASSING


def test_size_branch_beyond_the_listed_sizes_is_not_passed_at_n7():
    v = _v_each("size_branch_beyond.py", ("exact", "modular"), "adv-size-branch-beyond", size="7,2")
    assert none_passes(v), v


def test_a_size_read_through_a_shape_or_a_text_is_no_read():
    """Sizes and tracers carry no number (it lives with the trace, behind int(n)): the claim that looks for
    7 in the private shape of X or in the text of X reads nothing, so it states X^T X = I at every size,
    proved for all n and passed at n = 7; the claim that reads the text of its size uses the door, which
    is refused with symbolic sizes (free: not proved), and is false at n = 7 only."""
    v = verdicts("size_branch_shape.py", "free")
    assert v["adv-size-branch-shape"] == "proved" and v["adv-size-branch-text"] not in PASSING, v
    methods = ("exact", "modular", "float")
    each7, each3 = verdicts_each("size_branch_shape.py", methods, size="7,2"), verdicts_each("size_branch_shape.py", methods)
    for method in methods:
        at7, at3 = each7[method], each3[method]
        assert at7["adv-size-branch-shape"] in PASSING and at7["adv-size-branch-text"] == "fails", (method, at7)
        assert at3["adv-size-branch-text"] in PASSING, (method, at3)


def test_size_read_by_introspection_reads_no_number():
    """A claim that traces with symbolic sizes is never traced at a number (that graph is its graph at every
    size): the trace's state (_numbers) and the frames of its thread (the local n of trace()) hold no 7 at
    any size, so both claims are X^T X = I at every size, with one graph: proved for every n, and passed at
    n = 7 by the graph the proof is about (before: proved for every n, while their graph at n = 7 was X)."""
    for method, v in verdicts_each("size_read_by_introspection.py", ("free", "exact", "modular"), size="7,2").items():
        assert set(v) == {"adv-size-by-trace", "adv-size-by-frames"} and set(v.values()) <= set(PASSING), (method, v)
        if method == "free":
            assert set(v.values()) == {"proved"}, v
def test_size_read_from_the_command_is_one_graph_in_every_run():
    """Closed: the file is traced in a spawned interpreter whose command line is neutral (python -I -B -c ...),
    which holds none of the run's options and, in namespaces, sees no process of the run (stiefelsym.run.sandbox):
    X^T X - I in every run, proved for every n and passed at (7,2)."""
    free = _v("size_read_from_the_command.py", "free", "adv-size-by-command")
    at7 = _v("size_read_from_the_command.py", "exact", "adv-size-by-command", size="7,2")
    assert free == "proved" and at7 in PASSING, (free, at7)


# -- B. a primitive of the claims file runs its Python at evaluation time --------------------------

def test_user_primitive_cannot_tell_the_method():
    v = _v_each("user_primitive_method.py", ("modular", "rational", "float", "free"), "adv-primitive-method")
    assert none_passes(v), v


# -- C. a function handed to the scene is traced once per object -----------------------------------

def test_function_changed_between_uses_is_not_proved():
    v = _v_each("function_traced_once.py", ("exact", "modular", "float"), "adv-function-once")
    assert none_passes(v), v


def test_function_changed_between_uses_true_claim_does_not_fail():
    v = _v_each("function_traced_once_true_fails.py", ("exact", "modular"), "adv-function-once-true")
    assert "fails" not in v.values(), v


# -- D. the graph cache is keyed by the claim's callable (its __hash__/__eq__) ----------------------

def test_cache_collision_does_not_prove_a_false_claim():
    v = _v_each("graph_cache_collision.py", ("exact", "modular", "free"), "adv-cache-false")
    assert none_passes(v), v


# -- E. named(): any object of the claim's reaches the methods' arithmetic --------------------------

def test_named_constant_cannot_tell_the_method():
    v = _v_each("named_constant.py", ("exact", "float", "free"), "adv-named-shifty")
    assert none_passes(v), v


# -- F. engine state changed by the claims file (catalog claims included) ---------------------------

def test_claims_file_cannot_change_a_catalog_verdict():
    assert _v("primitive_override.py", "modular", "magnetic-form-kirillov-kostant",
              ids=("magnetic-form-kirillov-kostant",)) != "fails"


def test_registered_backend_cannot_pass_a_false_claim():
    assert _v("registered_backend.py", "modular", "adv-backend") not in PASSING


# -- G. results files that `stiefelsym check` accepts -----------------------------------------------

def test_check_rejects_a_free_record_edited_to_fails(tmp_path):
    out = tmp_path / "rep"
    r = cli("verify", "--claims", str(ROOT / "examples" / "my_claims.py"), "--method", "free",
            "--report-dir", str(out))
    assert r.returncode == 0, r.stdout + r.stderr
    payload = json.loads((out / "results.json").read_text())
    for rec in payload["results"]:
        assert rec["verdict"] == "proved"
        rec["verdict"], rec["certificate_data"] = "fails", None
    (out / "forged.json").write_text(json.dumps(payload))
    assert cli("check", str(out / "forged.json")).returncode == 1


def test_check_rejects_a_catalog_verdict_made_by_a_claims_file(tmp_path):
    """The claims file that overrides an engine step is refused when it is loaded (exit 2), so no
    results file carries the verdict it would make; `check` with it is refused the same way."""
    out = tmp_path / "rep"
    r = cli("verify", "magnetic-form-kirillov-kostant", "--claims", str(HERE / "primitive_override_check.py"),
            "--size", "3,2", "--method", "modular", "--report-dir", str(out))
    assert r.returncode == 2 and "registered by the engine" in r.stderr, r.stderr
    assert not (out / "results.json").exists()


# -- H. coordinates read through an engine value (opaque sides) with a product and a trace -----------

def test_coordinate_read_through_an_engine_value_is_seen():
    v = _v_each("coordinate_via_engine_units.py", ("exact", "auto"), "adv-units")
    assert none_passes(v), v


# -- I. digest collisions: an engine name is hashed unescaped ---------------------------------------

def test_distinct_graphs_have_distinct_digests():
    """Engine names are quoted in the digest's text, so a name cannot pose as more of the line (and a
    claims file can no longer register names: see digest_collision.py, which now fails to load)."""
    from stiefelsym.ir.graph import Graph, Named

    a, b = Graph(), Graph()
    a.output = a.add("list", (Named("adv.zero,%1"),))
    z = b.add("const", (0,))
    b.output = b.add("list", (Named("adv.zero"), z))
    assert a.args != b.args and a.digest() != b.digest()
    r = cli("verify", "--claims", str(HERE / "digest_collision.py"), "--method", "exact", "--size", "3,2")
    assert r.returncode == 2 and "registered by the engine" in r.stderr, r.stderr


# -- J. claim code writes the graph's cache of derived data (s._t.g.cache) --------------------------

def test_poisoned_float_range_does_not_make_numeric():
    assert _v("graph_cache_poisoned.py", "float", "adv-poisoned-wide", ids=("adv-poisoned-wide",)) not in PASSING


def test_poisoned_digest_does_not_pass_at_n4():
    v = _v_each("graph_cache_poisoned.py", ("exact", "modular", "float", "free"), "adv-poisoned-digest", size="4,2",
                ids=("adv-poisoned-digest",))
    assert none_passes(v), v


def test_check_rejects_a_record_whose_evidence_was_edited(tmp_path):
    out = tmp_path / "rep"
    r = cli("verify", "my-prep", "--claims", str(ROOT / "examples" / "my_claims.py"), "--size", "3,2",
            "--method", "modular", "--report-dir", str(out))
    assert r.returncode == 0, r.stdout + r.stderr
    payload = json.loads((out / "results.json").read_text())
    rec = payload["results"][0]
    assert rec["verdict"] == "checked"
    rec.update(false_pass_bound=1e-300, reductions=["symbolic (exact, identically zero)"],
               certificate="identically zero (symbolic)", expected=False)
    (out / "forged.json").write_text(json.dumps(payload))
    assert cli("check", str(out / "forged.json")).returncode == 1


# -- K. absorption with an exact constant inside the float range --------------------------------------

def test_absorbed_residual_is_not_numeric():
    assert _v("float_absorption_exact_constant.py", "float", "adv-absorbed-int") not in PASSING


# -- L. the method's live scene is reachable from claim code while it is traced ------------------------

def test_claim_code_cannot_find_the_live_scene():
    v = _v_each("live_scene_by_gc.py", ("exact", "modular", "rational"), "adv-live-scene")
    assert none_passes(v), v


def test_claim_code_cannot_read_the_method_from_frames():
    v = _v_each("method_by_frames.py", ("exact", "modular", "rational"), "adv-frames")
    assert none_passes(v), v


def test_check_rejects_a_verdict_obtained_by_reading_frames(tmp_path):
    """Traced in a thread of its own before any method runs, the claim finds no method in its frames:
    the false claim fails, and `check` (which traces the same way) agrees with the record."""
    out = tmp_path / "rep"
    cli("verify", "--claims", str(HERE / "method_by_frames.py"), "--size", "3,2", "--method", "modular",
        "--report-dir", str(out))
    payload = json.loads((out / "results.json").read_text())
    assert [r["verdict"] for r in payload["results"]] == ["fails"]      # X = 0, false
    assert cli("check", str(out / "results.json")).returncode == 0
    payload["results"][0]["verdict"] = "checked"
    (out / "results.json").write_text(json.dumps(payload))
    assert cli("check", str(out / "results.json")).returncode == 1


def test_patched_evaluator_cannot_pass_a_false_claim():
    v = _v_each("evaluator_patched.py", ("exact", "modular", "free"), "adv-evaluator")
    assert none_passes(v), v


# -- M. the operator letter on so(n) (dimension-free) used wrongly -------------------------------

OPERATOR_FALSE = ("two-operators-equal", "operator-self-pairing-zero", "operator-additive-wrong",
                  "operator-symmetric-no-trace", "operator-on-phi-vs-psi-size")


def test_operator_letter_misuse_is_never_proved_for_all_sizes():
    v = verdicts("operator_letter_misuse.py", "free")
    assert all(v[c] not in PASSING for c in OPERATOR_FALSE), v


def test_operator_letter_misuse_fails_at_a_fixed_size():
    for method, v in verdicts_each("operator_letter_misuse.py", ("exact", "modular", "float"), size="3,2").items():
        assert all(v[c] == "fails" for c in OPERATOR_FALSE), (method, v)


# -- N. r_is_n declared on a SizeSpec whose own sizes have r < n ----------------------------------

def test_r_is_n_with_sizes_r_less_than_n_is_refused():
    """Since stop 85 (its sweep's M2) a statement of sizes whose listed sizes its own fields exclude is refused when
    the claim is registered: the file has no verdict (before, the free method did not prove its false claims and
    the fixed-size methods refuted them at (3,2))."""
    run = run_verify("square_sizes_inconsistent.py", "free", "3,2", ())
    assert run.returncode == 2 and "which its own statement of sizes" in run.stderr, run.stderr[-600:]
    run = cli("verify", "--claims", str(HERE / "square_sizes_inconsistent.py"), "--method", "modular")
    assert run.returncode == 2 and "excludes" in run.stderr, run.stderr[-600:]


# -- O. a function handed to the scene closes over a value of the enclosing scene -------------------

CAPTURED = ("adv-captured-grad", "adv-captured-at-point", "adv-captured-point-value", "adv-captured-scalar",
            "adv-captured-default-flow", "adv-captured-d-at-point", "adv-captured-twisted-flow-at-point",
            "adv-nested-gradient", "adv-nested-derivative", "adv-nested-bracket", "adv-nested-bracket-ambient")
#: true claims the free method proves (nested functions keep their own letters)
CAPTURED_TRUE = ("adv-captured-control", "adv-nested-gradient-control", "adv-nested-derivative-control")


def test_captured_base_value_is_not_proved():
    """The free scene evaluates a function it is handed on a scene of its own whose X, P are fresh letters,
    so a captured base value stays a constant of the function (gradients, flows); the scene at another
    point refuses a function that returns the letters X, P on fresh letters (a capture it would move)."""
    v = verdicts("captured_base_value.py", "free")
    assert all(v[c] not in PASSING for c in CAPTURED), v
    assert all(v[c] == "proved" for c in CAPTURED_TRUE), v


def test_captured_base_value_is_not_passed_at_a_fixed_size():
    for method, v in verdicts_each("captured_base_value.py", ("exact", "modular", "float"), size="3,2").items():
        assert all(v[c] not in PASSING for c in CAPTURED), (method, v)


def test_captured_value_at_a_double_point_is_not_proved():
    """The derivative at a point (X, Y, Xdot, Ydot) of the double system evaluates F at fresh letters too, so
    the scene's DY that F closes over is not moved with the point (the derivative is r, not 0); the
    Euler-Lagrange equations of the double system evaluate T and U at fresh letters the same way."""
    v = verdicts("captured_double_point.py", "free")
    assert v["adv-captured-double-derivative"] not in PASSING and v["adv-captured-double-control"] == "proved", v
    for method, v in verdicts_each("captured_double_point.py", ("exact", "modular"), size="3,2").items():
        assert v["adv-captured-double-derivative"] not in PASSING and v["adv-captured-double-control"] in PASSING, \
            (method, v)


def test_multipliers_of_a_hamiltonian_holding_a_flow_are_not_proved():
    """Inside a function the free scene solves a flow's multipliers modulo the constraints: the function's Dirac
    flow is kept (proved, checked), its multipliers are refused (they depend on it off T*V)."""
    v = verdicts("nested_flow_multipliers.py", "free")
    assert v["adv-nested-multipliers"] not in PASSING and v["adv-nested-dirac-flow"] == "proved", v
    v = verdicts("nested_flow_multipliers.py", "modular", size="3,2")
    assert v["adv-nested-multipliers"] == "fails" and v["adv-nested-dirac-flow"] in PASSING, v


# -- P. column letters at one r, the scene at another point, the letters at r = n (no hole found) -----

COLUMNS_R2 = ("adv-cols-complete-in-n", "adv-cols-swapped", "adv-cols-range-r", "adv-cols-r23", "adv-cols-r2-trace",
              "adv-cols-r2-phi", "adv-cols-r2-phi-sign", "adv-point-minusP-flow", "adv-point-off-TV",
              "adv-point-scaled", "adv-point-rotated-r2", "adv-point-magnetic-reflected", "adv-op-point-flow",
              "adv-op-point-grad", "adv-mix-er-e2", "adv-mix-lead-e2")
COLUMNS_R1 = ("adv-cols-r1-e2", "adv-cols-r1-xxt", "adv-cols-r1-pt", "adv-mix-er-e1-r1", "adv-r1-pxt", "adv-r1-xxtp",
              "adv-r1-commute")
SQUARE_R_N = ("adv-last-sign", "adv-square-xtp-zero", "adv-square-pxt-sym", "adv-last-lead-one")


def test_column_letters_misuse_is_never_proved():
    v = verdicts("columns_one_r.py", "free")
    assert all(v[c] not in PASSING for c in COLUMNS_R2 + COLUMNS_R1), v
    assert v["adv-point-reflected-control"] == "proved" and v["adv-op-point-flow-control"] == "proved", v
    assert v["adv-r1-scalar-control"] == "proved", v
    v = verdicts("columns_square.py", "free")
    assert all(v[c] not in PASSING for c in SQUARE_R_N + ("adv-last-every-r",)), v


@pytest.mark.parametrize("method", [pytest.param("exact", marks=pytest.mark.slow), "modular", FLOAT_SLOW])
def test_column_letters_misuse_fails_at_a_fixed_size(method):
    at_r2 = tuple(c for c in COLUMNS_R2 if c not in ("adv-cols-range-r", "adv-cols-r23"))   # true at r = 2
    v = verdicts("columns_one_r.py", method, size="3,2", ids=at_r2 + ("adv-point-reflected-control",))
    assert all(v[c] == "fails" for c in at_r2) and v["adv-point-reflected-control"] in PASSING, v
    v = verdicts("columns_one_r.py", method, size="3,3", ids=("adv-cols-r23",))
    assert v["adv-cols-r23"] == "fails", v
    v = verdicts("columns_one_r.py", method, size="3,1", ids=COLUMNS_R1 + ("adv-cols-range-r",))
    assert v["adv-cols-r1-xxt"] == "fails" and v["adv-cols-r1-pt"] == "fails" and v["adv-mix-er-e1-r1"] == "fails", v
    assert v["adv-cols-r1-e2"] not in PASSING and v["adv-cols-range-r"] not in PASSING, v
    assert all(v[c] == "fails" for c in ("adv-r1-pxt", "adv-r1-xxtp", "adv-r1-commute")), v
    v = verdicts("columns_square.py", method, size="3,3", ids=SQUARE_R_N)
    assert all(v[c] == "fails" for c in SQUARE_R_N), v
    v = verdicts("columns_square.py", method, size="3,2", ids=("adv-last-every-r",))
    assert v["adv-last-every-r"] == "fails", v


NONZERO_FALSE = ("adv-cols-nonzero-vanishes", "adv-cols-nonzero-at-n2")


def test_false_nonvanishing_with_columns_is_not_passed():
    """Statements of nonvanishing that are false at r = 2 (at every n, resp. at n = 2): the free method
    leaves them undecided, every fixed-size method says fails at (2,2)."""
    v = verdicts("columns_one_r.py", "free", ids=NONZERO_FALSE)
    assert all(v[c] not in PASSING for c in NONZERO_FALSE), v
    for method, v in verdicts_each("columns_one_r.py", ("exact", "modular", "float"), size="2,2",
                                   ids=NONZERO_FALSE).items():
        assert all(v[c] == "fails" for c in NONZERO_FALSE), (method, v)


def test_check_rejects_a_free_proof_grafted_onto_another_claim(tmp_path):
    """The certificate of the proved control, copied into the record of a false claim at r = 2 with the
    verdict proved: `check` re-runs free records and rejects it."""
    out = tmp_path / "rep"
    cli("verify", "adv-point-reflected-control", "adv-cols-r2-phi", "--claims", str(HERE / "columns_one_r.py"),
        "--method", "free", "--report-dir", str(out))
    payload = json.loads((out / "results.json").read_text())
    recs = {r["claim"]: r for r in payload["results"]}
    good, bad = recs["adv-point-reflected-control"], recs["adv-cols-r2-phi"]
    assert good["verdict"] == "proved" and bad["verdict"] == "undecided"
    for k in ("verdict", "certificate", "certificate_data", "checks", "message", "residual", "derivation"):
        if k in good:
            bad[k] = good[k]
    (out / "forged.json").write_text(json.dumps(payload))
    assert cli("check", str(out / "forged.json")).returncode == 1


# -- Q. a scalar that vanishes at one stated size divides the residual ------------------------------

POLE = ("adv-pole-n4", "adv-pole-n4-phi")
#: c = tr(I_n) - tr(I_r): 0 at every r = n, 2 at the probe's size (3,1)
POLE_RN = "adv-pole-r-eq-n"


def test_division_by_a_scalar_vanishing_at_a_stated_size_is_not_proved():
    v = verdicts("division_at_one_size.py", "free")
    assert all(v[c] not in PASSING for c in POLE + (POLE_RN,)), v


def test_division_by_zero_at_n4_is_not_passed():
    methods = ("exact", "modular", "float")
    for method, v in verdicts_each("division_at_one_size.py", methods, size="4,2", ids=POLE).items():
        assert all(v[c] not in PASSING for c in POLE), (method, v)
    v = _v_each("division_at_one_size.py", methods, POLE_RN, size="3,3", ids=(POLE_RN,))
    assert none_passes(v), v


# -- R. the independent checker: coefficients with a pole where the hypothesis holds -----------------

def _term(coef, hyp, in_trace, left=(), right=()):
    return {"coef": coef, "hyp": hyp, "in_trace": in_trace, "left": list(left), "right": list(right),
            "word": [], "traces": [], "transposed": False}


def _one_equals_zero(terms):
    """A certificate of the residual 1 (a 1x1 entry): a proof of 1 = 0."""
    return {"format": "stiefelsym-cofactor-1", "letters": {}, "entries": [{
        "position": "r", "type": ["1", "1"], "residual": [{"coef": "1", "word": [], "traces": []}],
        "terms": terms}]}


#: 1 = -(r-2)^{-1} tr(E1E1^T + E2E2^T - I_r) + (r-2)^{-1}(E1^T E1 - 1) + (r-2)^{-1}(E2^T E2 - 1): an identity
#: of rational functions of r, whose coefficients have their pole at r = 2, where the hypothesis holds
ONE_AT_R2 = _one_equals_zero([_term("-1/(r-2)", "E1E1t+E2E2t", True), _term("1/(r-2)", "E1tE1", False),
                              _term("1/(r-2)", "E2tE2", False)])
#: 1 = (r-n)^{-1} (tr(X X^T - I_n) - tr(X^T X - I_r)): the pole at r = n, where X X^T = I_n holds
ONE_AT_RN = _one_equals_zero([_term("1/(r-n)", "XXt", True), _term("-1/(r-n)", "XtX", True)])
#: 1 = (1-r)^{-1} (tr(E1E1^T - I_r) - (E1^T E1 - 1)): the pole at r = 1, where E1E1^T = I_r holds
ONE_AT_R1 = _one_equals_zero([_term("1/(1-r)", "E1E1t", True), _term("-1/(1-r)", "E1tE1", False)])


@pytest.mark.parametrize("cert", [ONE_AT_R2, ONE_AT_RN, ONE_AT_R1], ids=["r2", "rn", "r1"])
def test_checker_rejects_a_certificate_with_a_pole_where_its_hypothesis_holds(cert, tmp_path):
    from stiefelsym.certificate_check import check_certificate

    assert not check_certificate(cert).accepted
    path = tmp_path / "forged.json"
    path.write_text(json.dumps({"results": [{"claim": "adv-one", "method": "free", "verdict": "proved",
                                             "certificate_data": cert}]}))
    r = subprocess.run([sys.executable, "-m", "stiefelsym.certificate_check", str(path)], cwd=ROOT,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 1, r.stdout


# -- S. a true claim whose free certificate is rejected (operator letter, columns, another point) -----

def test_true_claim_with_operator_columns_at_a_point_is_not_an_error():
    """A 1x1 piece of an operator letter's argument (E2^T E2 after the rotation J) is taken out of it as a
    scalar when the letter is made, so the letters of the normal form and of the certificate agree."""
    assert _v("certificate_operator_columns_point.py", "free", "adv-cert-operator-columns-point") == "proved"


OPCOLS_TRUE, OPCOLS_FALSE = ("adv-opcols-linear", "adv-opcols-unit-piece"), "adv-opcols-linear-sign"


def test_operator_argument_pieces_are_proved_with_an_accepted_certificate(tmp_path):
    out = tmp_path / "rep"
    cli("verify", "--claims", str(HERE / "certificate_operator_columns_pieces.py"), "--method", "free",
        "--report-dir", str(out))
    recs = {r["claim"]: r for r in json.loads((out / "results.json").read_text())["results"]}
    assert all(recs[c]["verdict"] == "proved" for c in OPCOLS_TRUE), recs
    assert recs[OPCOLS_FALSE]["verdict"] not in PASSING, recs[OPCOLS_FALSE]
    r = subprocess.run([sys.executable, "-m", "stiefelsym.certificate_check", str(out / "results.json")], cwd=ROOT,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr


def test_operator_argument_pieces_at_a_fixed_size():
    for method, v in verdicts_each("certificate_operator_columns_pieces.py", ("exact", "modular", "float"),
                                   size="3,2").items():
        assert all(v[c] in PASSING for c in OPCOLS_TRUE) and v[OPCOLS_FALSE] == "fails", (method, v)


def test_true_claim_with_operator_columns_at_a_point_is_checked():
    v = _v_each("certificate_operator_columns_point.py", ("exact", "modular"), "adv-cert-operator-columns-point")
    assert set(v.values()) <= set(PASSING), v


# -- T. derivatives and gradients as graph rewrites, the complex scene, so(r), graphs as claims ---------

D_TRUE = ("adv-d-nontangent-as-written", "adv-d-alias")
D_FALSE = ("adv-d-nontangent", "adv-d-inner-flow-moving", "adv-d-resolvent-sign")


def test_derivative_rewrites_along_flows_are_decided_as_written():
    """A flow that is not tangent is differentiated as written (both the rewrite and the scene); a second
    derivative whose inner flow moves with the point is not taken for one along a constant flow."""
    for method, v in verdicts_each("derivative_flows.py", ("exact", "modular", "free")).items():
        assert all(v[c] in PASSING for c in D_TRUE), (method, v)
        assert all(v[c] not in PASSING for c in D_FALSE), (method, v)
        if method != "free":
            assert all(v[c] == "fails" for c in D_FALSE), (method, v)


CX_OP_TRUE = ("adv-cx-tangent", "adv-op-r-symmetric-arg")
CX_OP_FALSE = ("adv-cx-conj-transpose", "adv-cx-tangent-half", "adv-op-r-n-same-name", "adv-fg-sym-r")


@pytest.mark.parametrize("method", ["modular", "free"])
def test_complex_scene_and_operator_on_so_r(method):
    v = verdicts("complex_and_operators.py", method)
    assert all(v[c] in PASSING for c in CX_OP_TRUE), v
    assert all(v[c] not in PASSING for c in CX_OP_FALSE), v
    if method == "modular":
        assert all(v[c] == "fails" for c in CX_OP_FALSE), v


@pytest.mark.parametrize("method", ["modular", "free"])
def test_forged_graphs_are_refused_by_the_replay(method):
    v = verdicts("graph_claim_forged.py", method)
    assert v["adv-rp-true"] in PASSING, v
    assert v["adv-rp-private"] not in PASSING and v["adv-rp-engine-step"] not in PASSING, v
    if method == "modular":
        assert v["adv-rp-private"] == v["adv-rp-engine-step"] == "error", v


def test_form_gradient_of_a_form_that_is_not_affine_is_not_decided():
    """The coordinate scenes check that the form is affine (at a generic element of the space, parameters
    of the engine's own) before they sum over a basis: refused, as the dimension-free scene refuses it."""
    for method, v in verdicts_each("form_gradient_not_affine.py", ("exact", "modular", "float")).items():
        assert v["adv-fg-quadratic-secant"] == v["adv-fg-quadratic-at-zero"] == "error", (method, v)
        assert v["adv-fg-quadratic-along-flow"] == "error", (method, v)        # the dual part of the check
        assert v["adv-fg-affine-in-gradient"] in PASSING and v["adv-fg-affine-along-flow"] in PASSING, (method, v)


def test_form_gradient_of_a_form_that_is_not_affine_is_refused_by_free():
    v = verdicts("form_gradient_not_affine.py", "free")
    assert all(x not in PASSING for x in v.values()), v


def test_gradient_in_x_does_not_read_the_declared_degree():
    """gradient_in_x is one engine step that derives the form's degree in x itself (the tensor's declared
    degree is not read): the true claim passes, the false one fails, a form that is no polynomial is
    refused; the dimension-free method takes affine forms only and leaves the rest to the fixed sizes."""
    methods = ("exact", "modular", "float", "ball", "free")
    for method, v in verdicts_each("gradient_in_x_declared_degree.py", methods, size="3,3").items():
        if method == "free":
            assert all(x not in PASSING for x in v.values()) and len(v) == 3, v
            continue
        assert v["adv-gradient-in-x-declared-degree"] in PASSING, (method, v)
        assert v["adv-gradient-in-x-cubic-is-quadratic"] == "fails", (method, v)
        assert v["adv-gradient-in-x-rational"] == "error", (method, v)


# -- the derivative passes' rules, one expression each, and the degree of polynomial_gradient ----------

@pytest.mark.parametrize("method", [EXACT_SLOW, "modular", "float", "free"])
def test_the_derivative_rules_and_the_gradient_step_on_probes(method):
    v = verdicts("derivative_pass_probes.py", method)
    assert len(v) == 17, v
    if method == "free":
        assert all(x != "proved" for k, x in v.items() if not k.endswith("-true")), v
        for k in ("adv-dp-d-realify-true", "adv-dp-d-Y-true", "adv-dp-grad-killing-rect-true"):
            assert v[k] == "proved", v
        return
    for k, x in v.items():
        if k.endswith("-true"):
            assert x in PASSING, (k, v)
        elif k.startswith("adv-dp-pg-"):
            assert x == "error", (k, v)
        else:
            assert x == "fails", (k, v)


# -- the complex point: conj, realify, and flows that move Zc ------------------------------------------

@pytest.mark.parametrize("method", [EXACT_SLOW, "modular", "float", "free"])
def test_the_complex_point_under_every_method(method):
    v = verdicts("complex_point_probes.py", method)
    assert len(v) == 14, v
    assert v["adv-cz-d-bad-key"] == "error", v
    if method == "free":
        assert all(x != "proved" for k, x in v.items() if not k.endswith("-true")), v
        assert v["adv-cz-d-true"] == v["adv-cz-d-conj-false"] == "undecided", v
        assert v["adv-cz-conjZtconjZ-true"] == v["adv-cz-conj-product-true"] == "proved", v
        return
    # exact: the complex point's symbolic solve is beyond its budget at (3, 2) (inconclusive, never wrong)
    budget = ("inconclusive",) if method == "exact" else ()
    for k, x in v.items():
        if k.endswith("-true"):
            assert x in PASSING + budget, (k, v)
        elif k != "adv-cz-d-bad-key":
            assert x in ("fails",) + budget, (k, v)


# -- the operator letter's rules (sym_operator) ----------------------------------------------------

@pytest.mark.parametrize("method", ["modular", "free"])
def test_the_operator_rules_under_free_and_a_fixed_size(method):
    v = verdicts("operator_rules_probes.py", method)
    assert len(v) == 13, v
    for k, x in v.items():
        if k.endswith("-true"):
            assert x == ("proved" if method == "free" else "checked"), (k, v)
        else:
            assert x == ("undecided" if method == "free" else "fails"), (k, v)


# -- a resolvent at a spectral parameter that moves with the point (the derivative passes) ----------

def test_a_moving_spectral_parameter_is_differentiated():
    methods = ("exact", "modular", "float", "ball", "free")
    for method, v in verdicts_each("resolvent_at_moving_point.py", methods).items():
        assert v["adv-moving-mu-gradient"] not in PASSING and v["adv-moving-mu-bracket"] not in PASSING, (method, v)
        if method != "free":
            assert v["adv-moving-mu-gradient"] == "fails" and v["adv-moving-mu-gradient-true"] in PASSING, (method, v)


# -- V. the new letters of the free algebra (issue 23/20): S, D, C, Dn and R at a moving mu ---------

NEW_LETTERS = "new_letters_probes.py"
#: true for every S commuting with A, every pair of orthogonal blocks, every resolvent: proved everywhere
NEW_TRUE = ("adv-refl-commutes-A", "adv-refl-commutes-moving-resolvent", "adv-split-D-plus-C-idempotent",
            "adv-refl-derivative", "adv-refl-gradient", "adv-split-bracket", "adv-split-conjugated-idempotent",
            "adv-new-letters-symmetric", "adv-moving-mu-same-twice", "adv-mu-constant-through-XtX",
            "adv-kernel-annihilates", "adv-kernel-block-derivative")
#: false at (3,2): S against objects it does not commute with, a factor dropped, mu taken for its value
NEW_FALSE = ("adv-refl-commutes-A-plus-XXt", "adv-refl-commutes-Phi", "adv-moving-mu-vs-parameter",
             "adv-refl-derivative-zero", "adv-refl-bracket", "adv-refl-gradient-half", "adv-refl-conjugated-involution",
             "adv-new-letters-skew-wrong", "adv-kernel-annihilates-X", "adv-kernel-commutes-A", "adv-kernel-idempotent")
#: true at the fixed-size objects only (S_1, diag(I_2, 0), A diagonal, D + C = I_r), not for every such letter
NEW_FIXED_ONLY = ("adv-refl-Dn-commute", "adv-Dn-commutes-A", "adv-split-D-minus-C-square", "adv-kernel-multiple-of-projector")


def test_new_letters_free_verdicts():
    """No rule of S, D, C, Dn, R_m is used beyond its objects: S does not pass A + XXᵀ, Φ, Dn; Dn does not
    commute with A; D + C = I_r is not assumed; S is constant under s.d / s.gradient / s.bracket."""
    v = verdicts(NEW_LETTERS, "free")
    assert all(v[c] == "proved" for c in NEW_TRUE), v
    assert all(v[c] not in PASSING for c in NEW_FALSE + NEW_FIXED_ONLY + ("adv-split-bracket-mixed",)), v
    assert v["adv-moving-mu-two-values"] not in PASSING, v      # a second moving parameter: refused
    # (mu I - A) R(mu) = I with mu written out: mu is not its symbol m (undecided, never wrong)
    assert v["adv-moving-mu-rayleigh"] not in PASSING and v["adv-moving-mu-trA"] not in PASSING, v


def test_new_letters_fixed_size_verdicts():
    methods = ("exact", "modular")
    for method, v in verdicts_each(NEW_LETTERS, methods, size="3,2", ids=NEW_TRUE + NEW_FIXED_ONLY + NEW_FALSE).items():
        assert all(v[c] in PASSING for c in NEW_TRUE + NEW_FIXED_ONLY), (method, v)
        assert all(v[c] == "fails" for c in NEW_FALSE), (method, v)
    for method, v in verdicts_each(NEW_LETTERS, methods, size="4,3",
                                   ids=("adv-split-bracket-mixed", "adv-split-bracket")).items():
        assert v["adv-split-bracket-mixed"] == "fails" and v["adv-split-bracket"] in PASSING, (method, v)


def test_two_moving_parameters_fail_at_a_fixed_size():
    """R(tr PᵀP) = R(tr PᵀDnP) (false; refused by free): modular fails it (exact's symbolic inverse of the
    difference exceeds its budget at (3,2))."""
    assert _v(NEW_LETTERS, "modular", "adv-moving-mu-two-values", ids=("adv-moving-mu-two-values",)) == "fails"


def test_a_resolvent_at_the_eigenvalue_tr_a_is_not_passed_at_n1():
    """At n = 1, mu = tr A = a_1 is the eigenvalue of A: R(mu) exists at no point of that stated size."""
    v = _v_each(NEW_LETTERS, ("exact", "modular"), "adv-moving-mu-trA-commutes", size="1,1",
                ids=("adv-moving-mu-trA-commutes",))
    assert none_passes(v), v


def test_a_resolvent_at_the_eigenvalue_tr_a_is_not_proved_for_every_n():
    """A proof with a resolvent at a moving spectral parameter holds where that resolvent exists; the free
    method probes every stated size for it, and mu = tr A is the eigenvalue a_1 at n = 1: error."""
    assert _v(NEW_LETTERS, "free", "adv-moving-mu-trA-commutes") not in PASSING


#: mu = tr(Dn A (I - S))/2 is a_1 at every fixed size (Dn = diag(I_2, 0), S = S_1, A = diag(a))
EIGEN = ("adv-moving-mu-eigenvalue-commutes", "adv-moving-mu-eigenvalue-reflection", "adv-moving-mu-eigenvalue-trace")
EIGEN_OFF_PROBE = "adv-moving-mu-eigenvalue-off-probe"


def test_a_resolvent_at_an_eigenvalue_at_the_probe_size_is_not_proved():
    """The division probe of the free method finds R(a_1) singular: error, not proved."""
    v = verdicts(NEW_LETTERS, "free", ids=EIGEN)
    assert all(v[c] not in PASSING for c in EIGEN), v


@pytest.mark.parametrize("methods", [("exact", "modular"), pytest.param(("float",), marks=pytest.mark.slow)],
                         ids=["exact-modular", "float"])
def test_a_resolvent_at_an_eigenvalue_is_not_passed_at_a_fixed_size(methods):
    for size in ("3,2", "2,2"):
        for method, v in verdicts_each(NEW_LETTERS, methods, size=size, ids=EIGEN + (EIGEN_OFF_PROBE,)).items():
            assert all(v[c] not in PASSING for c in EIGEN + (EIGEN_OFF_PROBE,)), (size, method, v)
    v = _v_each(NEW_LETTERS, methods, EIGEN_OFF_PROBE, size="3,1", ids=(EIGEN_OFF_PROBE,))
    assert set(v.values()) <= set(PASSING), v


def test_a_resolvent_at_an_eigenvalue_off_the_probe_size_is_not_proved():
    """mu is a_1 at every stated size but (3,1): the probe at every stated size (a proof that used a moving
    spectral parameter) finds R(mu) singular at (2,2): error, not proved."""
    assert _v(NEW_LETTERS, "free", EIGEN_OFF_PROBE, ids=(EIGEN_OFF_PROBE,)) not in PASSING


def test_tr_sa_is_never_wrong():
    """tr(SA) = tr(AS) (true): the free scene ranks S last with S A -> A S, so the cyclic reduction of tr(AS)
    loops and it answers undecided today (an incompleteness, not a hole); never fails, and modular passes it."""
    assert _v(NEW_LETTERS, "free", "adv-refl-trace-SA", ids=("adv-refl-trace-SA",)) != "fails"
    assert _v(NEW_LETTERS, "modular", "adv-refl-trace-SA", ids=("adv-refl-trace-SA",)) in PASSING


def test_a_grafted_certificate_with_the_reflection_letter_is_rejected_by_check(tmp_path):
    """The certificate of S A = A S (hypothesis SrefA) grafted onto the record of (D + C)^2 = D + C, a claim with
    no S: the independent checker accepts it (it proves its own residual, which names S), `stiefelsym check`
    re-derives the claim's certificate and rejects the record."""
    run = cli("verify", "adv-refl-commutes-A", "adv-split-D-plus-C-idempotent", "--claims", str(HERE / NEW_LETTERS),
              "--method", "free", "--format", "json")
    payload = json.loads(run.stdout)
    by = {r["claim"]: r for r in payload["results"]}
    by["adv-split-D-plus-C-idempotent"]["certificate_data"] = by["adv-refl-commutes-A"]["certificate_data"]
    forged = tmp_path / "forged.json"
    forged.write_text(json.dumps(payload), encoding="utf-8")
    checked = cli("check", str(forged))
    assert checked.returncode == 1 and "REJECTED adv-split-D-plus-C-idempotent" in checked.stdout, checked.stdout


def test_a_proof_at_a_moving_mu_says_where_it_holds(tmp_path):
    """mu = a_1 at n = 7 only, beyond the stated sizes: the free proof is for every n, r at which R(mu)
    exists, and its certificate says so; at n = 7 no fixed-size method passes the claim."""
    cid = "adv-moving-mu-eigenvalue-beyond"
    run = cli("verify", cid, "--claims", str(HERE / NEW_LETTERS), "--method", "free", "--report-dir", str(tmp_path))
    import json
    (rec,) = json.loads((tmp_path / "results.json").read_text())["results"]
    assert run.returncode == 0 and rec["verdict"] == "proved", run.stdout
    assert "for every n, r at which the resolvent at the spectral parameter that moves with the point" \
        in rec["certificate"], rec["certificate"]
    assert _v(NEW_LETTERS, "modular", cid, size="7,2", ids=(cid,)) not in PASSING
