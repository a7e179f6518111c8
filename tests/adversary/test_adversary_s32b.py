"""Adversarial round on two changes: the exact method's chart that also reduces by O(r) acting on the right
(A11 diagonal) when the claim reads no coordinates of R^n or R^r, and the sealed loading of a user's claims
file (imported and traced in child processes, pure data to the verifying process).  As in
test_adversary.py: every run is in a fresh process, each test asserts the CORRECT outcome, and a route that
is open today is a strict xfail."""
import json
import os
import subprocess
import sys

import pytest

from adversary_cli import HERE, LINE, PASSING, ROOT, cli, verdicts  # noqa: E402,F401


# -- 1. the O(r) reduction of the exact chart: entries of XᵀAX picked through an opaque space ----------

OPAQUE = "s32b_opaque_block_tags.py"


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_an_entry_of_XtAX_through_an_opaque_space_is_not_proved(method):
    """s.mat(rows, ("r+so", "?")) columns and block([[M], [0_so]]) pick (XᵀAX)_12 without an entry read;
    the claim's graph visibly reads given matrices, so exact goes to the O(n) chart (A11 generic) and the
    false claim fails (it was proved before the graph-based fallback)."""
    v = verdicts(OPAQUE, method, ids=("adv-s32b-opaque-offdiag",))
    assert v["adv-s32b-opaque-offdiag"] not in PASSING, v


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_an_entry_of_XtAinvX_through_an_opaque_space_is_not_proved_metric(method):
    v = verdicts(OPAQUE, method, ids=("adv-s32b-opaque-offdiag-metric",))
    assert v["adv-s32b-opaque-offdiag-metric"] not in PASSING, v


def test_the_opaque_entry_picking_is_sound():
    """The controls: without the O(r) reduction (modular, Cayley chart) the claim fails; the same picking of
    (XᵀX)_12 = 0 (true) is proved by exact, so the hole above is the chart, not the picking."""
    v = verdicts(OPAQUE, "modular", ids=("adv-s32b-opaque-offdiag", "adv-s32b-opaque-offdiag-metric"))
    assert v == {"adv-s32b-opaque-offdiag": "fails", "adv-s32b-opaque-offdiag-metric": "fails"}, v
    assert verdicts(OPAQUE, "exact", ids=("adv-s32b-opaque-diag-control",))["adv-s32b-opaque-diag-control"] \
        == "proved"


COND = "s32b_constraint_basis_entries.py"


@pytest.mark.parametrize("cid", ["adv-s32b-cond-entry", "adv-s32b-cond-entry-metric"])
@pytest.mark.parametrize("method", ["exact", "auto"])
def test_an_entry_of_the_constraint_bracket_matrix_is_not_proved(method, cid):
    assert verdicts(COND, method, ids=(cid,))[cid] not in PASSING


def test_the_constraint_bracket_entry_claims_are_false():
    """The control: modular (Cayley chart, A = diag(a), no reduction) refutes both."""
    v = verdicts(COND, "modular")
    assert v == {"adv-s32b-cond-entry": "fails", "adv-s32b-cond-entry-metric": "fails"}, v


CORE = "s32b_small_core.py"


def test_solves_beyond_3x3_taken_by_the_small_core_rule():
    """The rule changes the budget, not the elimination (Bareiss with a pivot nonzero as a polynomial): the
    5x5 resolvent identity is proved (inconclusive before the rule), a false factor fails, and a singular
    matrix whose pattern 3 rows cover is refused as singular (error), never inverted."""
    v = verdicts(CORE, "exact", size="5,2", ids=("adv-s32b-core-resolvent", "adv-s32b-core-resolvent-false"))
    assert v == {"adv-s32b-core-resolvent": "proved", "adv-s32b-core-resolvent-false": "fails"}, v
    v = verdicts(CORE, "exact", size="4,2", ids=("adv-s32b-core-singular",))
    assert v["adv-s32b-core-singular"] not in PASSING, v


def test_check_rejects_the_chart_proofs_of_unrecorded_reads(tmp_path):
    cli("verify", "adv-s32b-opaque-offdiag", "adv-s32b-cond-entry", "--claims", str(HERE / OPAQUE), "--claims",
        str(HERE / COND), "--method", "exact", "--size", "3,2", "--report-dir", str(tmp_path))
    recs = json.loads((tmp_path / "results.json").read_text())["results"]
    passed = [r["claim"] for r in recs if r["verdict"] in PASSING]
    assert not passed or cli("check", str(tmp_path / "results.json")).returncode == 1, passed


# -- 2. sealed loading: the API still imports a claims file in the verifying process --------------------

API_RUN = """
from stiefelsym import api
res = api.verify(files=[{path!r}], sizes=[(3, 2)], methods=("exact",))
for r in res:
    print(r.claim, r.verdict)
"""


def test_api_verify_does_not_honour_a_review_flag_set_by_the_file():
    out = subprocess.run([sys.executable, "-c", API_RUN.format(path=str(HERE / "reviewed_flag_spoofed.py"))],
                         cwd=ROOT, capture_output=True, text=True, timeout=300)
    got = dict(line.split() for line in out.stdout.splitlines() if line.startswith("adv-"))
    assert got and all(v not in PASSING for v in got.values()), (got, out.stderr[-2000:])


# -- 3. sealed loading: the child writes a forged answer to the pipe itself --------------------------------

FORGED = "s32b_forged_pipe.py"


@pytest.mark.parametrize("method", ["exact", "modular", "free"])
def test_a_forged_answer_of_the_child_is_no_answer(method):
    """The file writes, from its import, a well-formed payload with reviewed = true, an admits table of its own
    and at (3,2) the graph of X_11 = 1 (false there) under a claim whose symbolic graph is XᵀX = I, on the newest
    pipe it finds, and ends its process.  Until stop 83 that was the tracing process's pipe to the verifying
    process, and the payload was read (each graph only as the claim's graph of symbolic sizes allows: XᵀX = I at
    every size, never X_11 = 1, and the review flag never read from the wire).  Since stop 83 the file is imported
    only in children of that process, each with a pipe of its own: the payload landed on the pipe of the child that
    lists the claims, which ended without listing them, and the file was refused (exit 2), with no verdict.  Since
    stop 85 a job holds no pipe but its own answer pipe, which is its standard error too: the file finds no pipe to
    write on, and its claim is verified as its code says (XᵀX = I_r, true at every size; no graph of X_11 = 1)."""
    out = cli("verify", "--claims", str(HERE / FORGED), "--method", method)
    assert out.returncode == 0, out.stderr[-2000:]
    verdicts = [m.group(2) for m in map(LINE.match, out.stdout.splitlines()) if m]
    assert verdicts and set(verdicts) <= {"proved", "checked"}, out.stdout


CHILD = "s32b_child_output.py"


@pytest.mark.parametrize("mode", ["", "exit", "stray"])
def test_what_the_child_prints_or_how_it_leaves_is_never_a_verdict(mode):
    """Forged verdict lines printed at import and while tracing (also to sys.__stdout__) go to standard
    error, never to the verdicts; a child that leaves early (status 0, no answer) is an error of the file (exit 2),
    not a file of claims.  Stray bytes before the answer: since stop 85 the only pipe a job holds is its answer pipe,
    its standard error too, which the file's search skips; the claim is then refuted as its code says."""
    env = dict(os.environ, STIEFELSYM_S32B_CHILD=mode)
    out = cli("verify", "--claims", str(HERE / CHILD), "--method", "exact", "--size", "3,2", env=env)
    assert "exact: proved" not in out.stdout, out.stdout
    if mode == "stray":
        assert [m.group(2) for m in map(LINE.match, out.stdout.splitlines()) if m] == ["fails"], out.stdout
    elif mode:
        assert out.returncode == 2 and not LINE.search(out.stdout), (out.returncode, out.stdout)
    else:
        assert [m.group(2) for m in map(LINE.match, out.stdout.splitlines()) if m] == ["fails"], out.stdout


PLUGIN_ARGS = ("--stiefelsym-method", "exact", "--stiefelsym-size", "3,2", "-q", "-p", "no:cacheprovider",
               "-c", os.devnull)


def test_the_pytest_plugin_does_not_honour_a_review_flag_set_by_the_file(tmp_path):
    f = tmp_path / "spoofed_claims.py"
    f.write_text((HERE / "reviewed_flag_spoofed.py").read_text())
    out = subprocess.run([sys.executable, "-m", "pytest", "--stiefelsym", f.name, *PLUGIN_ARGS, "--rootdir",
                          str(tmp_path)], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert "2 failed" in out.stdout, out.stdout[-2000:]


def test_a_claim_id_cannot_print_a_forged_verdict_line():
    out = cli("verify", "--claims", str(HERE / "s32b_claim_id_newline.py"), "--method", "exact", "--size", "3,2")
    passing = [m.group(0) for m in map(LINE.match, out.stdout.splitlines()) if m and m.group(2) in PASSING]
    # an id names the claim on every output line: one with a line break is refused when the claim is made
    assert not passing and out.returncode == 2 and "claim id" in out.stderr, out.stdout + out.stderr


# -- 4. the strict decoder --------------------------------------------------------------------------------

DECODER = """
import sys
from stiefelsym.run.userfile import WireError, _loads, _value, _graph
bad = [b'1.5', b'NaN', b'[1e400]', b'{{"x": Infinity}}', b'\\xff', b'[' * 100000 + b']' * 100000]
for data in bad:
    try:
        _loads(data)
    except WireError:
        continue
    print("accepted", data[:20])
nested = {{"t": [1]}}
for _ in range(100000):
    nested = {{"t": [nested]}}
for v in ({{"s": [1, "x", 3]}}, {{"s": [1, "n", 1.5]}}, {{"f": [1, 0]}}, {{"r": -1}}, {{"t": [1], "l": []}},
          {{"q": 5}}, {{"z": 1}}, nested):
    try:
        _value(v)
    except (WireError, RecursionError):
        continue
    print("decoded", str(v)[:40])
try:
    _graph({{"ops": ["scene"], "args": [{{"t": []}}], "output": {{"r": 0}}, "fns": 0, "sizes": None, "x": 1}})
except Exception as exc:
    print("graph refused", type(exc).__name__)
print("done")
"""


def test_the_strict_decoder_refuses_what_is_not_the_ir():
    """Floats, NaN, infinities, bytes that are not UTF-8, nesting beyond the recursion limit, sizes of another
    space, zero denominators, negative references, two tags in one value and unknown tags never decode."""
    out = subprocess.run([sys.executable, "-c", DECODER.format()], cwd=ROOT, capture_output=True, text=True,
                         timeout=120)
    lines = out.stdout.splitlines()
    assert lines and lines[-1] == "done", out.stderr[-2000:]
    assert not [x for x in lines if x.startswith(("accepted", "decoded"))], lines
