"""Fourth round: the dimension-free certificates bound to their claims in `stiefelsym report`, the metric
realization's multipliers, claims stated at a union of one-r families in a user's file, rank statements next to
residuals under the float confirmation, and sizes written as ints in a graph of symbolic sizes.  As before: every
run is the CLI in a fresh process, each test asserts the CORRECT outcome, and a route open today is a strict
xfail."""
import json
import re

import pytest

from adversary_cli import HERE, PASSING, ROOT, cli
from adversary_replay import namespaces

#: a verdict line with its method: "<claim> (n,r) <method>: <verdict>" or "<claim> all n, r free: <verdict>"
METHOD_LINE = re.compile(r"^(\S+) (?:\(\d+,\d+\)|all n, r) (\w+): (\w+)")
FIXED = ("exact", "modular", "rational", "float", "ball", "auto")


def parse_all(stdout):
    """{(claim, method): verdict} of the verdict lines of a run's standard output."""
    return {(m.group(1), m.group(2)): m.group(3) for m in map(METHOD_LINE.match, stdout.splitlines()) if m}


def run_fixed(claims_file, size="3,2", ids=()):
    """{(claim, method): verdict} of one run of every fixed-size method at one size."""
    args = ["verify", *ids, "--claims", str(HERE / claims_file), "--size", size, "--jobs", "1"]
    for m in FIXED:
        args += ["--method", m]
    return parse_all(cli(*args).stdout)


def run_free(claims_file, ids=()):
    return {c: v for (c, _m), v in parse_all(cli("verify", *ids, "--claims", str(HERE / claims_file), "--method",
                                                 "free", "--jobs", "1").stdout).items()}


def of(got, cid):
    return {m: v for (c, m), v in got.items() if c == cid}


def never_passes(got, cid):
    cells = of(got, cid)
    assert cells and not set(cells.values()) & set(PASSING), (cid, cells)


def never_fails(got, cid):
    cells = of(got, cid)
    assert cells and "fails" not in cells.values(), (cid, cells)


# -- AJ. a dimension-free certificate moved to another claim ---------------------------------------------------

GRAFT = "s34_grafted_certificate.py"
GRAFTS = [("adv-s34-graft-true", "adv-s34-graft-false"), ("adv-s34-graft-true-metric", "adv-s34-graft-false-metric"),
          ("adv-s34-graft-true", "adv-s34-graft-false-metric")]


@pytest.fixture(scope="module")
def graft_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("graft") / "run"
    run = cli("verify", "--claims", str(HERE / GRAFT), "--method", "free", "--jobs", "1", "--report-dir", str(out))
    got = {c: v for (c, _m), v in parse_all(run.stdout).items()}
    assert got == {"adv-s34-graft-true": "proved", "adv-s34-graft-false": "undecided",
                   "adv-s34-graft-true-metric": "proved", "adv-s34-graft-false-metric": "undecided"}, got
    return out / "results.json"


def _graft(results, donor, target, path):
    payload = json.loads(results.read_text())
    rs = {r["claim"]: r for r in payload["results"]}
    for k in ("verdict", "certificate", "certificate_data", "reductions", "derivation", "checks", "residual",
              "message"):
        rs[target][k] = rs[donor].get(k)
    path.write_text(json.dumps(payload))
    return path


@pytest.mark.parametrize("donor,target", GRAFTS)
def test_report_refuses_a_certificate_moved_to_another_claim(graft_run, tmp_path, donor, target):
    """The checker accepts the moved certificate (it expands to its own residual); `report` rendered the false
    claim as proved for every n and r and counted it among the statements that hold.  Closed: `report`
    re-derives every proof for all n, r on its registered claim and compares certificates, as `check` does."""
    forged = _graft(graft_run, donor, target, tmp_path / "forged.json")
    out = cli("report", "--results", str(forged), "--report-dir", str(tmp_path / "rep"))
    assert out.returncode == 2 and "certificate is not the one the claim's graph gives" in out.stderr, \
        (out.returncode, out.stdout[-800:], out.stderr[-800:])
    assert not (tmp_path / "rep" / "verification.md").exists()


def test_the_honest_results_are_rendered(graft_run, tmp_path):
    """The control: the run's own results file is rendered (the re-derived certificates are the recorded ones)."""
    out = cli("report", "--results", str(graft_run), "--report-dir", str(tmp_path / "rep"))
    assert out.returncode == 0, out.stderr[-800:]
    assert "adv-s34-graft-true" in (tmp_path / "rep" / "verification.md").read_text()


@pytest.mark.slow
def test_check_rejects_the_moved_certificate(graft_run, tmp_path):
    forged = _graft(graft_run, *GRAFTS[0], tmp_path / "forged.json")
    out = cli("check", str(forged))
    assert out.returncode == 1 and "REJECTED adv-s34-graft-false" in out.stdout, (out.returncode, out.stdout)


def _checker(path):
    import subprocess
    import sys
    return subprocess.run([sys.executable, "-m", "stiefelsym.certificate_check", str(path)], capture_output=True,
                          text=True, timeout=120, cwd=ROOT)


def test_the_checker_binds_a_certificate_to_the_record_it_sits_in(graft_run, tmp_path):
    """A certificate says which claim and graph it is about (written with it by the free method): the standalone
    checker refuses it in another claim's record (it expands to its own residual, which is why it was accepted
    before), and for the run's own records it prints what each proves."""
    forged = _graft(graft_run, *GRAFTS[0], tmp_path / "forged.json")
    out = _checker(forged)
    assert out.returncode == 1, out.stdout
    assert "adv-s34-graft-false: REJECTED: the certificate is about claim adv-s34-graft-true" in out.stdout, out.stdout
    honest = _checker(graft_run)
    assert honest.returncode == 0, honest.stdout
    assert "adv-s34-graft-true: accepted" in honest.stdout and "proves, for the graph " in honest.stdout
    digest = {r["claim"]: r["digest"] for r in json.loads(graft_run.read_text())["results"]}["adv-s34-graft-true"]
    assert f"for the graph {digest} of claim adv-s34-graft-true" in honest.stdout and " = 0" in honest.stdout


def test_what_the_standalone_checker_cannot_bind_report_does(graft_run, tmp_path):
    """A certificate that does not say what it is about is refused; one moved with its ``about`` rewritten to the
    record's claim and digest is accepted by the standalone checker (it cannot trace the claim: the docs say so),
    and refused by `report` (and `check`), which derive the certificate again from the claim's graph."""
    payload = json.loads(graft_run.read_text())
    for r in payload["results"]:
        if r.get("certificate_data"):
            r["certificate_data"].pop("about")
    (tmp_path / "bare.json").write_text(json.dumps(payload))
    out = _checker(tmp_path / "bare.json")
    assert out.returncode == 1 and "does not say which claim and graph it is about" in out.stdout, out.stdout
    donor, target = GRAFTS[0]
    forged = _graft(graft_run, donor, target, tmp_path / "forged.json")
    payload = json.loads(forged.read_text())
    rec = next(r for r in payload["results"] if r["claim"] == target)
    rec["certificate_data"]["about"] = {"claim": target, "digest": rec["digest"]}
    forged.write_text(json.dumps(payload))
    assert f"{target}: accepted" in _checker(forged).stdout
    out = cli("report", "--results", str(forged), "--report-dir", str(tmp_path / "rep"))
    assert out.returncode == 2 and "certificate is not the one the claim's graph gives" in out.stderr, out.stderr[-800:]


# -- AK. the multipliers of the metric realization --------------------------------------------------------------

METRIC = "s34_metric_multipliers.py"
METRIC_FALSE = ("adv-s34-metric-pi-zero", "adv-s34-metric-trace-lambda", "adv-s34-metric-lambda-square",
                "adv-s34-metric-potential-conserved", "adv-s34-metric-lambda-of-neumann")
METRIC_TRUE = ("adv-s34-metric-two-lambdas", "adv-s34-metric-relation", "adv-s34-metric-energy")


@pytest.fixture(scope="module")
def metric_runs():
    return run_fixed(METRIC), run_free(METRIC)


@pytest.mark.parametrize("cid", METRIC_FALSE)
def test_false_statements_about_the_metric_multipliers_pass_under_no_method(metric_runs, cid):
    fixed, free = metric_runs
    never_passes(fixed, cid)
    assert of(fixed, cid).get("modular") == "fails"
    assert free[cid] == "undecided", free


@pytest.mark.parametrize("cid", METRIC_TRUE)
def test_true_statements_about_the_metric_multipliers_never_fail(metric_runs, cid):
    fixed, free = metric_runs
    never_fails(fixed, cid)
    assert free[cid] in ("proved", "undecided"), free


def test_the_relation_of_the_multiplier_is_proved_for_every_n_r(metric_runs):
    assert metric_runs[1]["adv-s34-metric-relation"] == "proved"


def test_the_energy_of_a_metric_flow_with_a_potential_is_proved(metric_runs):
    """A true claim answered `error` by free: the flow of ½tr(PᵀA⁻¹P) + tr(XᵀAX) has the relation ρ reduced by the
    rules (−2XᵀA⁻¹AX → −2I_r), and the checker compared it with the derivative as derived, without the rules
    ("certificate rejected: the relation of Lambda:1 is not d/dt ...").  Closed: the certificate carries the
    difference of the two in the ideal of the constraints (``derived``), which the checker re-checks
    (tests/test_free_metric_derived.py has its corruptions)."""
    assert metric_runs[1]["adv-s34-metric-energy"] == "proved"


def test_a_multiplier_flow_with_pi_not_zero_is_left_to_the_fixed_size_methods(metric_runs):
    """The free scene refuses Π != 0 (no closed form); the fixed-size scene's multiplier flow has the form of
    (dot_XP) (X' = H_P − XΠ) also in the metric realization, not the Dirac flow's X' = H_P − A⁻¹XΠ: it fails there.
    No verdict contradicts the free method's (it proves nothing where Π != 0)."""
    fixed, free = metric_runs
    assert free["adv-s34-metric-mflow-is-dflow"] == "undecided"
    assert of(fixed, "adv-s34-metric-mflow-is-dflow").get("modular") == "fails"


# -- AL. a union of one-r families in a user's file -------------------------------------------------------------

UNION = "s34_union_sizes.py"
#: (claim, a size where it is false)
UNION_FALSE = [("adv-s34-union-xxtp", "3,1"), ("adv-s34-union-psi", "3,3"), ("adv-s34-union-psi-12", "3,2"),
               ("adv-s34-union-xxtp-2n", "3,2")]
UNION_TRUE = [("adv-s34-union-true", "3,1"), ("adv-s34-union-true", "3,3"), ("adv-s34-union-r1-true", "3,1")]


@pytest.fixture(scope="module")
def union_free():
    return run_free(UNION)


@pytest.mark.parametrize("cid,size", UNION_FALSE)
def test_a_union_of_r_does_not_lend_one_familys_hypothesis_to_another(union_free, cid, size):
    assert union_free[cid] == "undecided", union_free
    got = run_fixed(UNION, size, ids=(cid,))
    never_passes(got, cid)
    assert of(got, cid).get("modular") == "fails"


@pytest.mark.parametrize("cid,size", UNION_TRUE)
def test_a_claim_true_on_its_union_never_fails(union_free, cid, size):
    assert union_free[cid] in ("proved", "undecided"), union_free
    never_fails(run_fixed(UNION, size, ids=(cid,)), cid)


@pytest.mark.parametrize("size", ["3,2", "17,5"])
def test_a_size_outside_the_union_is_refused(size):
    """(3,2) and (17,5) are outside r in (1, n): refused (exit 2), also beyond the child's table of sizes."""
    out = cli("verify", "adv-s34-union-true", "--claims", str(HERE / UNION), "--size", size, "--method", "modular")
    assert out.returncode == 2 and "outside" in out.stderr, (out.returncode, out.stdout[-500:], out.stderr[-500:])


# -- AM. rank statements next to residuals: the float confirmation ---------------------------------------------

RANKS = "s34_rank_with_residuals.py"
RANK_FALSE = ("adv-s34-rank-every-point", "adv-s34-rank-too-high", "adv-s34-rank-too-low")


@pytest.fixture(scope="module")
def rank_runs():
    return run_fixed(RANKS), run_free(RANKS)


@pytest.mark.parametrize("cid", RANK_FALSE)
def test_a_false_rank_next_to_a_true_residual_passes_under_no_method(rank_runs, cid):
    fixed, free = rank_runs
    never_passes(fixed, cid)
    # a rank at every point with the stated rank over the function field and no constant maximal minor is
    # undecided by the exact method (it finds no point where the rank drops; a true such statement, the
    # Jacobian of (cond_XP), was called false): never passed, never refuted without a witness
    exact = "undecided" if cid == "adv-s34-rank-every-point" else "fails"
    assert of(fixed, cid)["exact"] == exact and of(fixed, cid)["float"] == "undecided"
    assert free[cid] == "undecided"


# -- AN. sizes written as ints in a graph of symbolic sizes -----------------------------------------------------

INTS = "s34_int_sized_blocks.py"


def test_an_int_sized_block_is_not_proved_for_every_n_r():
    free = run_free(INTS)
    assert set(free.values()) == {"undecided"}, free


def test_an_int_sized_block_beyond_the_listed_sizes_is_an_error():
    got = run_fixed(INTS, "4,2", ids=("adv-s34-int-size-n",))
    assert set(of(got, "adv-s34-int-size-n").values()) == {"error"}, got


def test_int_sized_blocks_at_a_listed_size():
    got = run_fixed(INTS)
    never_fails(got, "adv-s34-int-size-n")
    never_fails(got, "adv-s34-int-size-r")
    never_passes(got, "adv-s34-int-size-false")


# -- AO. a module of a lazily imported library's name on the import path ---------------------------------------

ON_PATH = "s34_module_on_the_path.py"


def _scratch_cwd(tmp_path, how="module"):
    cwd = tmp_path / "cwd"
    cwd.mkdir()
    (cwd / "S34_SCRATCH_CWD").write_text(how)
    return cwd


def _verify_in(cwd, tmp_path, *methods, confine="spawn"):
    """The run in ``cwd``; with the plain spawn (``confine="spawn"``), where the file writes with the user's
    rights, or in namespaces, where it writes nowhere but its own private /tmp."""
    import os
    import subprocess
    import sys

    from stiefelsym.run.sandbox import CONFINE_ENV
    args = [sys.executable, "-m", "stiefelsym", "verify", "--claims", str(HERE / ON_PATH), "--size", "3,2",
            "--jobs", "1", "--report-dir", str(tmp_path / "rep")]
    for m in methods:
        args += ["--method", m]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    env.pop(CONFINE_ENV, None)
    if confine == "spawn":
        env[CONFINE_ENV] = "spawn"
    return subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=300)


@pytest.mark.parametrize("method", ["exact", "free", "auto"])
def test_in_namespaces_the_file_puts_no_module_on_the_import_path(tmp_path, method):
    """In namespaces the same file writes nothing the verifying process can see (its /tmp is private, every
    other mount read-only): no module appears in the working directory, and its false claim is not passed."""
    if not namespaces():
        pytest.skip("no user + pid + mount namespaces here (unshare)")
    cwd = _scratch_cwd(tmp_path)
    out = _verify_in(cwd, tmp_path, method, confine="namespaces")
    assert not (cwd / "sympy.py").exists() and not (cwd / "platformdirs.py").exists()
    assert not list(cwd.glob("S34_IMPORTED_IN_*")) and "Traceback" not in out.stderr
    assert "adv-s34-path-false (3,2)" not in out.stdout or ": proved" not in out.stdout, out.stdout[-800:]
    assert out.returncode != 0, (out.stdout[-800:], out.stderr[-800:])


@pytest.mark.parametrize("method", ["exact", "free", "auto"])
def test_a_module_put_on_the_import_path_by_the_files_child_changes_no_verdict(tmp_path, method):
    """The child writes platformdirs.py and sympy.py into the working directory (sys.path[0] under python -m);
    the verifying process imported them after the child had run (the cost model's platformdirs, the exact
    method's sympy), and their profile hook made Xᵀ X = 2 I_r `proved` (exact: proved, exit 0, results.json
    proved).  Closed: the digest of every top-level module on the import path (confine.path_modules) is taken
    before the first fork and compared when the child returns, as the package's files are: exit 2, the files
    named, nothing imported from them, nothing written."""
    cwd = _scratch_cwd(tmp_path)
    out = _verify_in(cwd, tmp_path, method)
    assert (cwd / "sympy.py").is_file() and (cwd / "platformdirs.py").is_file()     # the child wrote them
    assert out.returncode == 2, (out.returncode, out.stdout[-800:], out.stderr[-800:])
    assert "changed on disk" in out.stderr and "sympy.py" in out.stderr and "Traceback" not in out.stderr
    assert not list(cwd.glob("S34_IMPORTED_IN_*")), "a module the child wrote was imported"
    assert not (tmp_path / "rep" / "results.json").exists()
    assert "proved" not in out.stdout


@pytest.mark.parametrize("how,written", [("package", "sympy/__init__.py"), ("bytecode", "sympy.pyc")])
def test_a_package_or_byte_code_put_on_the_import_path_changes_no_verdict(tmp_path, how, written):
    """The same route with a package folder of the library's name, or byte code without a source: closed alike."""
    cwd = _scratch_cwd(tmp_path, how)
    out = _verify_in(cwd, tmp_path, "exact")
    assert (cwd / written).is_file()
    assert out.returncode == 2 and "changed on disk" in out.stderr and written.split("/")[0] in out.stderr, \
        (out.returncode, out.stdout[-800:], out.stderr[-800:])
    assert not list(cwd.glob("S34_IMPORTED_IN_*")) and "proved" not in out.stdout


def test_the_claim_of_the_module_route_fails_where_the_file_writes_nothing(tmp_path):
    """The control: without the scratch marker the file writes nothing and its false claim fails."""
    cwd = tmp_path / "plain"
    cwd.mkdir()
    out = _verify_in(cwd, tmp_path, "exact")
    assert "adv-s34-path-false (3,2) exact: fails" in out.stdout, (out.stdout[-800:], out.stderr[-800:])
    assert not list(cwd.iterdir())


# -- AP. the other fields of a record, malformed ----------------------------------------------------------------

ODD_FIELDS = [("reductions", 5), ("seconds", "fast"), ("false_pass_bound", "tiny"), ("message", {"a": 1}),
              ("expected", "yes"), ("witness", "x"), ("derivation", "a derivation"), ("certificate", [1]),
              ("residual", [1, 2]), ("digest", [1]), ("certificate_data", [1]), ("change", 7),
              ("checks", [{"name": "x", "status": "zero", "degree": "high"}])]


@pytest.mark.parametrize("key,value", ODD_FIELDS)
def test_report_and_check_refuse_a_record_with_a_malformed_field(graft_run, tmp_path, key, value):
    """A record's fields beyond those that name the run (AC): `report` answered a Python traceback for reductions,
    seconds, false_pass_bound and message of the wrong type, and rendered the others (a witness that is a string,
    an `expected` flag that is "yes").  Closed: `results.record_problems` checks the type of every field a run
    writes; `report` refuses the file (exit 2), `check` rejects the record."""
    payload = json.loads(graft_run.read_text())
    for r in payload["results"]:
        if r["claim"] == "adv-s34-graft-false":
            r[key] = value
    odd = tmp_path / "odd.json"
    odd.write_text(json.dumps(payload))
    out = cli("report", "--results", str(odd), "--report-dir", str(tmp_path / "rep"))
    assert out.returncode == 2 and "Traceback" not in out.stderr and key in out.stderr, \
        (out.returncode, out.stderr[-800:])
    out = cli("check", str(odd), "--no-rerun")
    assert out.returncode == 1 and "malformed" in out.stdout and "Traceback" not in out.stderr, \
        (out.returncode, out.stdout[-800:], out.stderr[-800:])


# -- AQ. a record's `expected` flag -----------------------------------------------------------------------------

def test_report_does_not_take_the_expected_flag_from_the_file(tmp_path):
    """`report` took a record's `expected` flag from the file (only `check` compared it with a run again): flipped on
    a false claim's honest `fails`, the report said every verdict is the one the catalog expects and counted the
    claim among the errata 'expected to fail as printed', though it documents no erratum (a failure hidden as a
    known one, not a passing verdict).  Closed: `report` recomputes the flag from the registered claim
    (`runner.expected_of`, the policy of every run) and refuses a record that says otherwise."""
    run = tmp_path / "run"
    cli("verify", "--claims", str(HERE / GRAFT), "adv-s34-graft-false", "--method", "modular", "--size", "3,2",
        "--jobs", "1", "--report-dir", str(run))
    payload = json.loads((run / "results.json").read_text())
    (record,) = payload["results"]
    assert (record["verdict"], record["expected"]) == ("fails", False)
    record["expected"] = True
    forged = tmp_path / "forged.json"
    forged.write_text(json.dumps(payload))
    out = cli("report", "--results", str(forged), "--report-dir", str(tmp_path / "rep"))
    assert out.returncode == 2 and "the claim's statement says otherwise" in out.stderr, out.stderr[-800:]
    assert not (tmp_path / "rep" / "verification.md").exists()
