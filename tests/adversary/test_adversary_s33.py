"""Adversarial round on the sealed loading (a user's file traced in child processes, its graphs replayed
here), the records bound to claims (`stiefelsym check`, `stiefelsym report`), the exact method's chart
reductions and the dimension-free memo.  As in test_adversary.py: every run is the CLI in a fresh process,
each test asserts the CORRECT outcome, and a route that is open today is a strict xfail."""
import json
import os
import re
import sys

import pytest

from adversary_cli import HERE, LINE, PASSING, ROOT, cli, verdicts, verdicts_each  # noqa: E402,F401


# -- AA. a budget outcome of the file's child replayed in the process that checks -------------------------

BUDGET = "s33_budget_replayed.py"
BUDGET_IDS = ("adv-s33-budget-false", "adv-s33-budget-ender")


def _budget_env(mode):
    return dict(os.environ, STIEFELSYM_S33_BUDGET=mode)


def _forged_budget_results(tmp_path, mode):
    """The run's results with the false claim's `fails` edited to `proved` (a forged record)."""
    out = tmp_path / "run"
    cli("verify", "--claims", str(HERE / BUDGET), "--method", "exact", "--size", "3,2", "--report-dir", str(out),
        env=_budget_env(mode))
    payload = json.loads((out / "results.json").read_text())
    got = {r["claim"]: r["verdict"] for r in payload["results"]}
    assert got == {"adv-s33-budget-false": "fails", "adv-s33-budget-ender": "error"}, got
    for r in payload["results"]:
        if r["claim"] == "adv-s33-budget-false":
            r["verdict"] = "proved"
    forged = tmp_path / "forged.json"
    forged.write_text(json.dumps(payload))
    return forged


#: a verdict line with its method: "<claim> (n,r) <method>: <verdict>" or "<claim> all n, r free: <verdict>"
METHOD_LINE = re.compile(r"^(\S+) (?:\(\d+,\d+\)|all n, r) (\w+): (\w+)")
ALL_METHODS = ("exact", "modular", "rational", "float", "ball", "auto")


def parse_all(stdout):
    """{(claim, method): verdict} of the verdict lines of a run's standard output."""
    return {(m.group(1), m.group(2)): m.group(3) for m in map(METHOD_LINE.match, stdout.splitlines()) if m}


def run_all(claims_file, ids=(), size="3,2", methods=ALL_METHODS, env=None, free=True):
    """{(claim, method): verdict} of one run of every fixed-size method at one size (and one of free)."""
    args = ["verify", *ids, "--claims", str(HERE / claims_file), "--size", size]
    for m in methods:
        args += ["--method", m]
    got = parse_all(cli(*args, env=env).stdout)
    if free:
        got.update(parse_all(cli("verify", *ids, "--claims", str(HERE / claims_file), "--method", "free",
                                 env=env).stdout))
    return got


@pytest.mark.slow
@pytest.mark.parametrize("mode", ["exit0", pytest.param("exit1", marks=pytest.mark.slow),
                                  pytest.param("kill", marks=pytest.mark.slow)])
def test_verify_answers_error_for_a_claim_whose_tracing_ends_its_process(mode):
    """In `verify` the replay runs in a worker: the claim that ends its tracing process is an error under
    every method, the false claim is never passed, whatever the file does."""
    got = run_all(BUDGET, env=_budget_env(mode))
    ender = {m: v for (c, m), v in got.items() if c == "adv-s33-budget-ender"}
    false = {m: v for (c, m), v in got.items() if c == "adv-s33-budget-false"}
    assert set(ender.values()) == {"error"} and len(ender) >= 7, ender
    assert false and not set(false.values()) & set(PASSING), false


def test_check_exit_status_is_not_the_files_choice(tmp_path):
    """A forged `proved` of a false claim, in a results file whose other claim's tracing leaves its process
    with status 0: check must reject the forged record and exit 1.  Closed (AA): the replay of the child's exit
    raises (userfile.TraceEnded), so check's own process goes on and exits 1."""
    forged = _forged_budget_results(tmp_path, "exit0")
    out = cli("check", str(forged), env=_budget_env("exit0"))
    assert out.returncode == 1, (out.returncode, out.stdout[-1500:])


@pytest.mark.slow
def test_check_rejects_the_forged_record_when_the_file_does_not_end_its_process(tmp_path):
    """The control: the same forged record with a file that ends nothing (its ender claim traced as usual in
    the check; in the run it was an error) is rejected with exit 1."""
    forged = _forged_budget_results(tmp_path, "exit1")
    out = cli("check", str(forged), env=_budget_env(""))
    assert out.returncode == 1 and "REJECTED adv-s33-budget-false" in out.stdout, (out.returncode, out.stdout)


@pytest.mark.slow
def test_check_is_not_killed_by_the_files_child(tmp_path):
    """Closed (AA): the replayed SIGKILL is an exception in check, not a signal to itself."""
    forged = _forged_budget_results(tmp_path, "kill")
    out = cli("check", str(forged), env=_budget_env("kill"))
    assert out.returncode == 1 and "records checked" in out.stdout, (out.returncode, out.stdout[-1500:])


def test_derive_of_a_false_claim_whose_tracing_exits_0_is_not_status_0():
    """Closed (AA): the replay raises; derive runs the free method guarded (an error, exit 1)."""
    out = cli("derive", "adv-s33-budget-ender", "--claims", str(HERE / BUDGET), env=_budget_env("exit0"))
    # what derive says of a claim it cannot prove: exit 1, its "% <claim> ..." line, no traceback
    assert out.returncode == 1 and out.stdout.startswith("% adv-s33-budget-ender") and "Traceback" not in out.stderr, \
        (out.returncode, out.stdout, out.stderr[-1500:])


@pytest.mark.slow
def test_derive_of_the_false_claim_is_not_status_0():
    """The control: without the exit, derive of the false claim exits 1 (not proved for all n, r)."""
    out = cli("derive", "adv-s33-budget-ender", "--claims", str(HERE / BUDGET), env=_budget_env(""))
    assert out.returncode == 1, (out.returncode, out.stdout)


# -- AB. a declared r contradicted beyond the range where the declaration is checked ----------------------

BEYOND = "s33_sizes_beyond_table.py"
BEYOND_FALSE = ("adv-s33-beyond-col1", "adv-s33-beyond-square", "adv-s33-beyond-square-xp",
                "adv-s33-beyond-square-where")


@pytest.mark.parametrize("method", ["free", pytest.param("auto", marks=pytest.mark.slow)])
def test_a_declared_r_contradicted_beyond_16_is_not_proved_for_every_size(method):
    """Closed (AB): a declared r is believed only when admits() is decided by the declared fields (a plain
    SizeSpec, or a user's plain statement rebuilt with `fields_first`, whose admits() conjoins them); a
    subclass's own admits() leaves the claim to the fixed-size methods."""
    run = cli("verify", *BEYOND_FALSE, "--claims", str(HERE / BEYOND), "--method", method)
    if run.returncode == 2 and "which its own statement of sizes" in run.stderr:
        return      # since stop 85: a statement whose listed sizes its fields exclude is refused when registered
    v = verdicts(BEYOND, method, ids=BEYOND_FALSE) if method == "free" else parse_all(run.stdout)
    got = {c: x for c, x in v.items()} if method == "free" else {c: x for (c, m), x in v.items() if m == "free"}
    assert set(got) == set(BEYOND_FALSE) and not set(got.values()) & set(PASSING), got


@pytest.mark.slow
def test_the_claims_declared_at_one_r_fail_at_17_2_which_their_statements_admit():
    """The control: (17, 2) is one of the claims' sizes (an explicit --size is checked against the statement
    and admitted), and every fixed-size method refutes them there (exact: beyond its time budget at n = 17);
    the claim stated at r = 1 alone is proved for every n."""
    got = run_all(BEYOND, ids=BEYOND_FALSE, size="17,2", methods=("modular", "rational", "float", "ball", "auto"),
                  free=False)
    # (auto runs modular here: its lines name modular)
    assert len(got) == 16 and set(got.values()) == {"fails"}, got
    assert verdicts(BEYOND, "free", ids=("adv-s33-beyond-control",)) == {"adv-s33-beyond-control": "proved"}


# -- AC. malformed results files: a traceback or a hang instead of a clear refusal -------------------------

RECORDS = "s33_records_base.py"


@pytest.fixture(scope="module")
def honest_results(tmp_path_factory):
    """The honest results of the two claims of s33_records_base.py (exact at (3,2), and free)."""
    out = tmp_path_factory.mktemp("records")
    cli("verify", "--claims", str(HERE / RECORDS), "--method", "exact", "--method", "free", "--size", "3,2",
        "--report-dir", str(out))
    payload = json.loads((out / "results.json").read_text())
    got = {(r["claim"], r["method"]): r["verdict"] for r in payload["results"]}
    assert got == {("adv-s33-rec-true", "exact"): "proved", ("adv-s33-rec-true", "free"): "proved",
                   ("adv-s33-rec-false", "exact"): "fails", ("adv-s33-rec-false", "free"): "undecided"}, got
    return payload


def _forge(payload, tmp_path, record=None, meta=None):
    """The payload with the false claim's exact record made `proved` and edited by ``record``, the meta by
    ``meta``; written to a file."""
    d = json.loads(json.dumps(payload))
    for r in d["results"]:
        if r["claim"] == "adv-s33-rec-false" and r["method"] == "exact":
            r["verdict"] = "proved"
            r.update(record or {})
    d["meta"].update(meta or {})
    path = tmp_path / "forged.json"
    path.write_text(json.dumps(d))
    return path


def _refused_cleanly(out):
    return out.returncode in (1, 2) and "Traceback" not in out.stderr


#: malformed fields and the command that answers them with a traceback today (ValueError, TypeError, KeyError
#: out of integrity.missing_runs / planned_runs, hard.hard_case, Registry.__contains__, report.py)
MALFORMED = {
    "claim-list": ({"claim": ["adv-s33-rec-false"]}, None),
    "claim-dict": ({"claim": {"id": "adv-s33-rec-false"}}, None),
    "n-list": ({"n": [3]}, None),
    "r-dict": ({"r": {"r": 2}}, None),
    "method-list": ({"method": ["exact"]}, None),
    "meta-sizes-three": (None, {"sizes": ["3,2,1"]}),
    "meta-sizes-int": (None, {"sizes": [32]}),
    "meta-methods-dict": (None, {"methods": [{"m": "exact"}]}),
    "meta-hard-list": (None, {"hard": ["near-pole"]}),
    "meta-hard-unknown": (None, {"hard": "no-such-case"}),
}
#: the ones `stiefelsym report` answers with a traceback (it reads no meta sizes, methods or hard case)
MALFORMED_REPORT = ("claim-list", "claim-dict", "n-list", "r-dict", "method-list")
FAST = ("claim-list",)


@pytest.mark.parametrize("case", [pytest.param(c, marks=[] if c in FAST else [pytest.mark.slow]) for c in MALFORMED])
def test_check_refuses_a_malformed_results_file_without_a_traceback(honest_results, tmp_path, case):
    """Closed (AC): check validates the meta field by field first (exit 2, results.meta_problems) and rejects a
    malformed record with its reason (exit 1, results.record_problems)."""
    record, meta = MALFORMED[case]
    out = cli("check", str(_forge(honest_results, tmp_path, record, meta)))
    assert _refused_cleanly(out), (out.returncode, out.stderr[-800:])


@pytest.mark.parametrize("case", [pytest.param(c, marks=[] if c in FAST else [pytest.mark.slow])
                                  for c in MALFORMED_REPORT])
def test_report_refuses_a_malformed_results_file_without_a_traceback(honest_results, tmp_path, case):
    """Closed (AC): report refuses a malformed record in one line (exit 2, results.record_problems)."""
    record, meta = MALFORMED[case]
    out = cli("report", "--results", str(_forge(honest_results, tmp_path, record, meta)), "--report-dir",
              str(tmp_path / "rep"))
    assert _refused_cleanly(out), (out.returncode, out.stderr[-800:])


@pytest.mark.parametrize("edit", [{"n": 3.0}, {"n": "3"}, {"n": True, "r": True}, {"method": "EXACT"},
                                  {"seed": "0"}, {"seed": 10 ** 30}, {"variant": ""}, {"n": -3, "r": -2},
                                  {"r": None}, {"digest": 5}, {"witness": "small"}])
@pytest.mark.slow
def test_check_rejects_a_forged_proved_with_odd_field_types(honest_results, tmp_path, edit):
    """Closed (no hole found): a forged `proved` whose size, method, seed, variant, digest or witness has an odd
    type or value is rejected (exit 1), with no traceback."""
    out = cli("check", str(_forge(honest_results, tmp_path, edit)))
    assert out.returncode == 1 and "Traceback" not in out.stderr and "rejected" in out.stdout, \
        (out.returncode, out.stdout[-500:], out.stderr[-500:])


@pytest.mark.slow
def test_check_rejects_a_forged_proved_with_another_claims_certificate(honest_results, tmp_path):
    """Closed: the true claim's (valid) free certificate on the false claim's record, made a proof for every
    n, r (n = r = None, or method free): the checker accepts the certificate, the re-derivation does not."""
    cert = next(r["certificate_data"] for r in honest_results["results"]
                if r["claim"] == "adv-s33-rec-true" and r["method"] == "free")
    for edit in ({"n": None, "r": None, "certificate_data": cert},
                 {"method": "free", "n": None, "r": None, "certificate_data": cert}):
        out = cli("check", str(_forge(honest_results, tmp_path, edit)))
        assert out.returncode == 1 and "REJECTED adv-s33-rec-false" in out.stdout, (edit.keys(), out.stdout[-800:])


@pytest.mark.slow
def test_check_of_a_results_file_with_a_huge_max_n_finishes(honest_results, tmp_path):
    """Closed (AC): a meta max_n beyond integrity.MAX_N_CHECKED is refused (exit 2) before any size is listed."""
    import subprocess
    import sys
    path = _forge(honest_results, tmp_path, meta={"max_n": 100000})
    try:
        out = subprocess.run([sys.executable, "-m", "stiefelsym", "check", str(path)], cwd=ROOT, capture_output=True,
                             text=True, timeout=60)
    except subprocess.TimeoutExpired:
        pytest.fail("check did not finish in 60 s")
    assert _refused_cleanly(out), (out.returncode, out.stderr[-800:])


# -- AD. honest records that `check` rejects, and a statement that makes `derive` print a traceback --------

HONEST = "s33_honest_errors.py"
RAISES = "s33_statement_raises.py"


def _honest_results(tmp_path):
    out = tmp_path / "honest"
    cli("verify", "--claims", str(HERE / HONEST), "--method", "exact", "--method", "free", "--size", "3,2",
        "--report-dir", str(out))
    payload = json.loads((out / "results.json").read_text())
    got = {(r["claim"], r["method"]): r["verdict"] for r in payload["results"]}
    assert got[("adv-s33-honest-divzero", "exact")] == "error", got
    # (since AB was closed the free method does not consult a subclass's admits(): the statement that raises
    # at (5,3) leaves the claim undecided, not in error)
    assert got[("adv-s33-honest-statement", "free")] == "undecided", got
    return out / "results.json"


def test_check_accepts_the_honest_records_of_runs_that_ended_in_error(tmp_path):
    """Closed (AD): an error record carries the digest of the graph it was met on (runner._guarded); check re-runs the free method guarded."""
    out = cli("check", str(_honest_results(tmp_path)))
    assert out.returncode == 0, out.stdout[-1500:]


@pytest.mark.parametrize("cid", ["adv-s33-raises-value",
                                 pytest.param("adv-s33-raises-zerodiv", marks=pytest.mark.slow)])
def test_derive_answers_a_raising_statement_without_a_traceback(cid):
    """Closed (AD): derive runs the free method guarded (runner.run_free_guarded): an error, exit 1."""
    out = cli("derive", cid, "--claims", str(HERE / RAISES))
    assert out.returncode == 1 and "Traceback" not in out.stderr, out.stderr[-800:]


def test_show_answers_a_raising_erratum_without_a_traceback():
    """Closed (AD): show evaluates the erratum sizes guarded and says that they raise."""
    out = cli("show", "adv-s33-raises-erratum", "--claims", str(HERE / RAISES))
    assert out.returncode in (0, 2) and "Traceback" not in out.stderr, out.stderr[-800:]


@pytest.mark.slow
def test_verify_answers_a_raising_statement_with_error():
    """The control: in `verify` the free run never passes (since AB was closed it does not consult a subclass's
    admits(), so the statement that raises is not asked: undecided); the fixed-size methods decide at (3,2)
    (the true claim proved or checked, the false one fails)."""
    got = run_all(RAISES, ids=("adv-s33-raises-value", "adv-s33-raises-zerodiv"), methods=("exact", "modular", "float"))
    assert got[("adv-s33-raises-value", "free")] == got[("adv-s33-raises-zerodiv", "free")] == "undecided", got
    assert got[("adv-s33-raises-value", "exact")] == "proved", got
    assert {got[("adv-s33-raises-zerodiv", m)] for m in ("exact", "modular", "float")} == {"fails"}, got


# -- AE. route K where the exact confirmation of `numeric` does not run ------------------------------------

ABSORB = "s33_numeric_unconfirmed.py"
ABSORB_IDS = ("adv-s33-absorb-X", "adv-s33-absorb-trace", "adv-s33-absorb-phi")


def test_absorbed_terms_are_not_numeric_at_13_2():
    """Closed (AE): float's and ball's `numeric` is confirmed at exact points mod p at every n."""
    got = run_all(ABSORB, size="13,2", methods=("float", "ball"), free=False)
    assert len(got) == 6 and not set(got.values()) & set(PASSING), got


def test_absorbed_terms_are_not_numeric_under_a_hard_case():
    """Closed (AE): under a hard case the confirmation runs at the hard point's exact parameters (here the
    case changes no parameter of the claim: at random points)."""
    out = cli("verify", "--claims", str(HERE / ABSORB), "--method", "float", "--method", "ball", "--size", "3,2",
              "--hard", "near-pole")
    got = parse_all(out.stdout)
    assert len(got) == 6 and not set(got.values()) & set(PASSING), got


@pytest.mark.slow
def test_absorbed_terms_fail_where_exact_arithmetic_looks():
    """The controls: at (13,2) modular, rational and auto refute the claims; at (3,2) without a hard case float
    and ball are confirmed at exact points and refute them; exact refutes them at (3,2)."""
    got = run_all(ABSORB, size="13,2", methods=("modular", "rational", "auto"), free=False)
    assert len(got) >= 6 and set(got.values()) == {"fails"}, got
    got = run_all(ABSORB, size="3,2", methods=("float", "ball", "exact"), free=False)
    assert len(got) == 9 and set(got.values()) == {"fails"}, got


# -- AF. the modular method's primes are known before the claim is stated ----------------------------------

SEEDED = "s33_seeded_primes.py"
SEEDED_IDS = ("adv-s33-seeded-sum", "adv-s33-seeded-matrix", "adv-s33-seeded-fraction", "adv-s33-seeded-absorbed")


def test_a_multiple_of_the_drawn_primes_is_not_checked_by_modular():
    """Closed (AF): every draw comes from methods.draw_key, the seed with the digest of the claim's traced
    graph; the primes the file computes at import are those of another key (its constant M is in the
    digest), so they are not the run's primes."""
    got = run_all(SEEDED, ids=SEEDED_IDS, methods=("modular",), free=False)
    assert len(got) == 4 and not set(got.values()) & set(PASSING), got


@pytest.mark.slow
def test_an_absorbed_multiple_of_the_drawn_primes_is_not_numeric():
    """Closed (AF): the confirmation's modular points come from the claim's own digest too."""
    got = run_all(SEEDED, ids=("adv-s33-seeded-absorbed",), methods=("float",), free=False)
    assert got and not set(got.values()) & set(PASSING), got


@pytest.mark.slow
def test_auto_does_not_pass_a_multiple_of_the_drawn_primes_at_13_2():
    """Closed (AF): auto's modular run draws its primes from the claim's own digest."""
    got = run_all(SEEDED, ids=("adv-s33-seeded-auto",), size="13,2", methods=("auto",), free=False)
    assert got and not set(got.values()) & set(PASSING), got


@pytest.mark.slow
def test_the_seeded_claims_are_false():
    """The controls: exact and rational refute all four (over Q the residual is M·tr(PᵀP), M·X, (M/3)·X, M·X)."""
    got = run_all(SEEDED, ids=SEEDED_IDS, methods=("exact", "rational"), free=False)
    assert len(got) == 8 and set(got.values()) == {"fails"}, got


POINTS = "s33_seeded_points.py"


def test_a_polynomial_vanishing_at_the_drawn_points_is_not_checked_by_rational():
    """Closed (AF): the rational points are drawn from the digest of the graph that holds the v_t."""
    got = run_all(POINTS, methods=("rational",), free=False)
    assert got and not set(got.values()) & set(PASSING), got


@pytest.mark.slow
def test_the_polynomial_vanishing_at_the_drawn_points_is_false():
    """The controls: exact, modular and ball refute it."""
    got = run_all(POINTS, methods=("exact", "modular", "ball"), free=False)
    assert len(got) == 3 and set(got.values()) == {"fails"}, got


@pytest.mark.slow
def test_derive_of_a_claim_whose_tracing_outlasts_its_budget_finishes():
    """Closed (AA): a replayed 'timeout' raises userfile.TraceEnded: derive answers error, exit 1."""
    import subprocess
    import sys
    try:
        out = subprocess.run([sys.executable, "-m", "stiefelsym", "derive", "adv-s33-budget-ender", "--claims",
                              str(HERE / BUDGET)], cwd=ROOT, capture_output=True, text=True, timeout=480,
                             env=_budget_env("sleep"))
    except subprocess.TimeoutExpired:
        pytest.fail("derive did not finish in 480 s (the tracing budget is 300 s)")
    assert out.returncode == 1, (out.returncode, out.stderr[-800:])


# -- AG. the division probe's fixed primes ------------------------------------------------------------------

PROBE = "s33_probe_primes.py"


@pytest.mark.slow
def test_a_divisor_that_is_a_multiple_of_the_probe_primes_is_not_an_error():
    """Closed (AG): the probe's primes are drawn from methods.draw_key (seed and graph digest), not fixed."""
    got = run_all(PROBE, methods=("exact", "auto"))
    assert len(got) == 4 and "error" not in got.values(), got


@pytest.mark.slow
def test_the_probe_prime_claims_pass_the_point_methods():
    """The control: modular, rational, float and ball pass the two true claims."""
    got = run_all(PROBE, methods=("modular", "rational", "float", "ball"), free=False)
    assert len(got) == 8 and set(got.values()) <= set(PASSING), got


# -- AH. a passing verdict for every n, r that no method gives, rendered by report -------------------------

@pytest.mark.parametrize("edit", [{"n": None, "r": None, "method": "modular", "verdict": "checked",
                                   "false_pass_bound": 1e-30},
                                  pytest.param({"n": None, "r": None, "method": "free", "verdict": "numeric"},
                                               marks=pytest.mark.slow)])
def test_report_refuses_a_passing_verdict_for_every_size_that_no_method_gives(honest_results, tmp_path, edit):
    """Closed (AH): a record with no size is the dimension-free method's, with one of its verdicts (integrity.size_method_problems): report refuses it (exit 2), check rejects it."""
    forged = _forge(honest_results, tmp_path, edit)
    out = cli("report", "--results", str(forged), "--report-dir", str(tmp_path / "rep"))
    assert out.returncode == 2, (out.returncode, out.stderr[-800:])


def test_report_refuses_a_results_file_with_a_planned_run_dropped(honest_results, tmp_path):
    """Closed (AH): report applies integrity.missing_runs as check does (exit 2)."""
    d = json.loads(json.dumps(honest_results))
    d["results"] = [r for r in d["results"] if (r["claim"], r["method"]) != ("adv-s33-rec-false", "exact")]
    path = tmp_path / "dropped.json"
    path.write_text(json.dumps(d))
    out = cli("report", "--results", str(path), "--report-dir", str(tmp_path / "rep"))
    assert out.returncode == 2, (out.returncode, out.stderr[-800:])


# -- AI. the engine's source on disk, rewritten by the file's child -----------------------------------------

DISK = "s33_engine_on_disk.py"


def _scratch_engine(tmp_path):
    """A copy of the package under tmp_path, marked as the scratch copy s33_engine_on_disk.py may rewrite."""
    import shutil
    root = tmp_path / "copy"
    shutil.copytree(ROOT / "stiefelsym", root / "stiefelsym", ignore=shutil.ignore_patterns("__pycache__"))
    (root / "stiefelsym" / "S33_SCRATCH_COPY").write_text("")
    return root


@pytest.mark.parametrize("confinement", ["spawn", "namespaces"])
def test_a_claims_file_that_rewrites_the_engine_on_disk_changes_no_verdict(tmp_path, confinement):
    """Closed (AI): the verifying process imports the whole package and takes the digest of its files before
    the first fork; a file changed when the child returns stops the run (exit 2, the file named, nothing
    written), and no module is read from disk after the child ran.  In namespaces the file cannot write the
    package at all (read-only there): its import fails, the run stops (exit 2), the copy is untouched."""
    import subprocess
    import sys
    root = _scratch_engine(tmp_path)
    env = dict(os.environ, PYTHONPATH=str(root))
    env.pop("STIEFELSYM_CONFINE", None)
    if confinement == "spawn":
        env["STIEFELSYM_CONFINE"] = "spawn"
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(HERE / DISK), "--method",
                          "exact", "--size", "3,2", "--report-dir", str(tmp_path / "rep")], cwd=root, env=env,
                         capture_output=True, text=True, timeout=300)
    assert "S33 PAYLOAD" not in (ROOT / "stiefelsym" / "reports" / "report.py").read_text()    # the engine itself untouched
    assert out.returncode == 2, (out.returncode, out.stderr[-800:])
    if confinement == "spawn" or "Read-only file system" not in out.stderr:
        assert "S33 PAYLOAD" in (root / "stiefelsym" / "reports" / "report.py").read_text(), out.stderr[-800:]  # the copy was
        assert "changed on disk" in out.stderr and "report.py" in out.stderr and "Traceback" not in out.stderr
    else:
        assert "S33 PAYLOAD" not in (root / "stiefelsym" / "reports" / "report.py").read_text()
    assert not (tmp_path / "rep" / "results.json").exists()
    assert "proved" not in out.stdout


LATER = "s33_results_rewritten_later.py"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the child subreaper is Linux's")
@pytest.mark.parametrize("confinement", ["spawn", "namespaces"])
def test_the_results_file_of_a_run_is_not_rewritten_after_it(tmp_path, confinement):
    """Closed (AI'): the verifying process is a child subreaper while the file's interpreter runs, and kills
    every process left under it (found in /proc) when it has ended, before anything is written; in namespaces
    the file's processes end with its pid namespace and cannot write the report folder (read-only there).
    The file is given the run's command line as its own sys.argv (it no longer inherits it)."""
    import time
    from adversary_cli import baked
    rep = tmp_path / "rep"
    args = ["verify", "--claims", None, "--method", "exact", "--size", "3,2", "--report-dir", str(rep)]
    args[2] = str(baked(HERE / LATER, {"STIEFELSYM_S33_DAEMON": "1"}, argv=["stiefelsym", *args[:2], *args[3:]]))
    env = dict(os.environ)
    env.pop("STIEFELSYM_CONFINE", None)
    if confinement == "spawn":
        env["STIEFELSYM_CONFINE"] = "spawn"
    out = cli(*args, env=env)
    assert "exact: fails" in out.stdout, out.stdout
    verdicts_seen = set()
    for _ in range(10):                 # the process it left acts within 0.1 s of the end of the run
        time.sleep(0.2)
        recs = json.loads((rep / "results.json").read_text())["results"]
        verdicts_seen |= {r["verdict"] for r in recs}
    assert verdicts_seen == {"fails"}, verdicts_seen


# -- the metric realization's multiplier letter (closed this session by design: Lambda is bound only by its relation)

METRIC_TRICKS = "s33_metric_tricks.py"
METRIC_FALSE = ("adv-s33-metric-lambda-closed-form", "adv-s33-metric-M-conserved", "adv-s33-metric-trace-lambda")


def test_false_statements_about_the_metric_flow_pass_under_no_method():
    """Λ in closed form (−PᵀA⁻²P, true only where XᵀA⁻¹X = I), XᵀA⁻¹X conserved, and tr(ΛM) with the wrong
    factor: the free method leaves them undecided (nonzero normal forms), the fixed-size methods refute them."""
    for method, got in verdicts_each(METRIC_TRICKS, ("free", "exact", "modular", "float")).items():
        assert set(got) == set(METRIC_FALSE), (method, got)
        assert not any(v in PASSING for v in got.values()), (method, got)
