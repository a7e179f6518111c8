"""Runs in worker processes: claims that try to escape their verdict (exit, die, hang, eat
memory, print into stdout), SIGTERM and Ctrl-C, the verdict policy, corrections at every
size, and the command line's other honest-output rules."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from stiefelsym import cli

from stiefelsym.run import runner
from stiefelsym.claims import Claim, Count, Rank, Size, admissible
from stiefelsym.run.pool import GIB, WorkerPool
from stiefelsym.results import Result, load_results, write_atomic

needs_fork = pytest.mark.skipif(not hasattr(os, "fork"), reason="workers need os.fork")

#: the tricks, as a claims file: each one's id, and the verdict it must end with
TRICKS = textwrap.dedent('''
    import os, signal, sys, time
    from stiefelsym import admissible, claim

    print("printed at import")
    os.write(1, b"written to fd 1 at import\\n")

    def one(id):
        return claim(id, paper="t", kind="id", section="9", sizes=admissible(n_max=1))

    class Escape(BaseException):
        pass

    @one("good")
    def good(s):
        print("printed by a claim")
        os.write(1, b"written to fd 1 by a claim\\n")
        sys.__stdout__.write("written to sys.__stdout__ by a claim\\n")
        sys.__stdout__.flush()
        return {"XtX": s.X.T @ s.X - s.Ir}

    @one("raises-system-exit")
    def raises_system_exit(s):
        raise SystemExit(0)

    @one("raises-base-exception")
    def raises_base_exception(s):
        raise Escape("out")

    @one("raises-keyboard-interrupt")
    def raises_keyboard_interrupt(s):
        raise KeyboardInterrupt

    @one("calls-os-exit")
    def calls_os_exit(s):
        os._exit(0)

    @one("segfaults")
    def segfaults(s):
        os.kill(os.getpid(), signal.SIGSEGV)
        time.sleep(5)

    @one("blocks-signals-and-sleeps")
    def blocks_signals_and_sleeps(s):
        signal.pthread_sigmask(signal.SIG_BLOCK, signal.valid_signals())
        time.sleep(600)

    @one("loops-forever")
    def loops_forever(s):
        while True:
            pass

    @one("allocates-without-bound")
    def allocates_without_bound(s):
        hoard = []
        while True:
            hoard.append(bytes(1 << 28))     # address space, not touched pages: fast
''')

TRICK_VERDICTS = {
    "good": ("checked", "", True),
    "raises-system-exit": ("error", "SystemExit", False),
    "raises-base-exception": ("error", "Escape: out", False),
    "raises-keyboard-interrupt": ("error", "KeyboardInterrupt", False),
    "calls-os-exit": ("error", "ended without a result (exited with status 0)", False),
    "segfaults": ("error", "ended without a result (killed by SIGSEGV)", False),
    "blocks-signals-and-sleeps": ("inconclusive", "exceeded its time budget", False),
    "loops-forever": ("inconclusive", "exceeded its time budget", False),
    "allocates-without-bound": ("error", "exceeded its memory budget of 3 GiB", False),
}


@pytest.fixture
def tricks(tmp_path) -> Path:
    path = tmp_path / "tricks.py"
    path.write_text(TRICKS)
    return path


def _env() -> dict[str, str]:
    return {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}


def stiefelsym(*args: str, cwd: Path, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "stiefelsym", *args], cwd=cwd, env=_env(),
                          capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)


# --------------------------------------------------------------------------- the pool

def _echo(x):
    return x


def _task(kind):
    if kind == "exit":
        os._exit(5)
    if kind == "sleep":
        time.sleep(60)
    if kind == "system-exit":
        raise SystemExit(2)
    if kind == "memory":
        hoard = []
        while True:
            hoard.append(bytes(1 << 28))
    return kind


@needs_fork
def test_pool_returns_outcomes_in_order_and_replaces_lost_workers():
    tasks = ["a", "exit", "b", "sleep", "system-exit", "memory", "c"]
    with WorkerPool(_task, workers=2, timeout=2, memory=3 * GIB) as pool:
        outcomes = list(pool.run(tasks))
        assert [i for i, _ in outcomes] == list(range(len(tasks)))
        kinds = [o.kind for _, o in outcomes]
        assert kinds == ["ok", "died", "ok", "timeout", "error", "memory", "ok"]
        assert [o.value for _, o in outcomes if o.kind == "ok"] == ["a", "b", "c"]
        assert "exited with status 5" in outcomes[1][1].message and "3 GiB" in outcomes[1][1].message
        assert outcomes[3][1].message == "exceeded its time budget of 2 s"
        assert "SystemExit" in outcomes[4][1].message
        assert "memory budget of 3 GiB" in outcomes[5][1].message
        assert [o.value for _, o in pool.run(["d"])] == ["d"]      # the pool goes on
    assert pool.workers == []


@needs_fork
def test_pool_leaves_no_process_behind():
    pool = WorkerPool(_task, workers=2, timeout=30)
    gen = pool.run(["a", "sleep", "b"])
    assert next(gen)[1].value == "a"
    pids = [w.pid for w in pool.workers]
    assert pids
    gen.close()                          # the consumer stops early: every worker is killed
    assert pool.workers == []
    for pid in pids:
        with pytest.raises(ChildProcessError):
            os.waitpid(pid, os.WNOHANG)


@needs_fork
@pytest.mark.parametrize("workers", [1, 2])
def test_pool_draws_from_an_iterator_only_for_a_free_worker(workers):
    """An iterator of tasks (the plan, looked at as it runs) is drawn from only when a worker is free: the
    parent's work on the next task overlaps the workers' on the others, never runs ahead of them."""
    consumed: list[int] = []
    drawn_after: list[int] = []
    tasks = ["a", "exit", "b", "sleep", "c", "d"]

    def source():
        for t in tasks:
            drawn_after.append(len(consumed))
            yield t

    with WorkerPool(_task, workers=workers, timeout=2) as pool:
        kinds = []
        for i, o in pool.run(source()):
            consumed.append(i)
            kinds.append(o.kind)
    assert consumed == list(range(len(tasks)))
    assert kinds == ["ok", "died", "ok", "timeout", "ok", "ok"]
    # task i is drawn once the outcomes of all but the last workers - 1 tasks before it were handed over
    assert all(after >= i - workers for i, after in enumerate(drawn_after))
    assert drawn_after[:workers] == [0] * workers


def test_pool_without_fork_runs_in_process():
    with WorkerPool(_task, workers=1, timeout=1, fork=False) as pool:
        outcomes = [o for _, o in pool.run(["a", "system-exit"])]
    assert [o.kind for o in outcomes] == ["ok", "error"]


# --------------------------------------------------------------------------- claims that cheat, in the runner

def _claim(cid, func, sizes=None, **kw) -> Claim:
    return Claim(id=cid, paper=("t",), kind=kw.pop("kind", "id"), section="9", func=func,
                 sizes=sizes or admissible(n_max=1), **kw)


def _ok(s):
    return {"XtX": s.X.T @ s.X - s.Ir}


def _exits(s):
    raise SystemExit(1)


def _sleeps(s):
    signal.pthread_sigmask(signal.SIG_BLOCK, signal.valid_signals())
    time.sleep(600)


@needs_fork
def test_every_method_runs_in_a_budgeted_worker():
    claims = [_claim("sleeps", _sleeps), _claim("exits", _exits), _claim("ok", _ok)]
    results = runner.verify(claims, methods=runner.METHODS, timeout=2, seed=0, jobs=3)
    for cid in ("sleeps", "exits", "ok"):     # auto at (1,1) is the exact method, unless stopped
        assert sorted(r.method for r in results if r.claim == cid) == \
            sorted(["exact" if cid == "ok" else "auto", "exact", "rational", "modular", "float", "ball", "free"])
    for r in results:
        if r.claim == "sleeps":
            assert r.verdict == "inconclusive" and not r.expected
            assert r.message == "exceeded its time budget of 2 s"
        elif r.claim == "exits":
            assert r.verdict == "error" and "SystemExit" in r.message and not r.expected
        else:
            assert r.verdict in ("proved", "checked", "numeric", "undecided") and r.expected


@needs_fork
def test_auto_is_budgeted_as_a_whole():
    res = runner.verify([_claim("sleeps", _sleeps)], sizes=[Size(1, 1)], methods=("auto",), timeout=2)
    assert [(r.method, r.verdict) for r in res] == [("auto", "inconclusive")]
    assert "--method auto" in res[0].rerun


@needs_fork
def test_parallel_workers_give_the_same_results_in_the_same_order():
    from stiefelsym.claims import load_catalog
    cat = load_catalog()
    claims = [cat.get(i) for i in ("adjoint-orbit-regularity", "invariant-metrics")] + \
        [_claim("sleeps", _sleeps, sizes=admissible(n_max=4, where=lambda n, r: (n, r) == (4, 2))),
         _claim("ok", _ok, sizes=admissible(n_max=3))]
    kw = dict(sizes=[Size(3, 1), Size(4, 1), Size(4, 2)], methods=("auto", "modular"), seed=3, timeout=2)
    seen = []
    one = runner.verify(claims, jobs=1, **kw)
    two = runner.verify(claims, jobs=2, on_result=seen.append, **kw)
    key = lambda r: (r.claim, r.variant, r.n, r.r, r.method, r.verdict, r.expected, r.seed, r.witness)
    assert [key(r) for r in one] == [key(r) for r in two] == [key(r) for r in seen]
    assert any(r.variant for r in one) and any(r.verdict == "inconclusive" for r in one)


# --------------------------------------------------------------------------- corrections

def _count_claim():
    def printed(s):
        return {"count": Count(s.n, 3 if s.n == 2 else s.n, "n")}
    c = _claim("count", printed, sizes=admissible(n_max=3), fails_at=lambda n, r: n == 2,
               erratum="n is miscounted at n = 2")
    c.correction("counted right")(lambda s: {"count": Count(s.n, s.n)})
    c.correction("wrong at n = 3")(lambda s: {"count": Count(s.n, 4 if s.n == 3 else s.n)})
    return c


@needs_fork
def test_corrections_run_at_every_planned_size_after_the_plan():
    c = _count_claim()
    results = runner.verify([c, _claim("ok", _ok)], methods=("modular",))
    printed = [r for r in results if r.variant is None]
    fixes = [r for r in results if r.variant is not None]
    assert results[:len(printed)] == printed                       # the plan first, then the corrections
    sizes = [(s.n, s.r) for s in c.sizes]
    assert [(r.n, r.r) for r in fixes] == sizes * 2
    assert [r.variant for r in fixes] == ["counted right"] * 6 + ["wrong at n = 3"] * 6
    assert all(r.verdict == "proved" and r.expected for r in fixes[:6])     # constants: exact over Q
    wrong = {(r.n, r.r): r for r in fixes[6:]}
    assert all(wrong[s].verdict == "fails" and not wrong[s].expected for s in sizes if s[0] == 3)
    assert all(r.verdict == "fails" and r.expected for r in printed if r.n == 2)


@needs_fork
def test_no_corrections_when_the_printed_claim_holds_at_the_planned_sizes():
    results = runner.verify([_count_claim()], sizes=[Size(3, 1)], methods=("modular",))
    assert [(r.variant, r.verdict) for r in results] == [(None, "proved")]


# --------------------------------------------------------------------------- verdict policy

def _result(verdict, method="modular", message="", n=3):
    return Result(claim="c", paper=["t"], section="9", kind="id", title="", statement="", n=n, r=1,
                  method=method, verdict=verdict, expected=False, seconds=0.0, seed=0, message=message)


@pytest.mark.parametrize("method", runner.METHODS)
def test_verdict_policy(method):
    holds = _claim("c", _ok)
    erratum = _claim("c", _ok, fails_at=lambda n, r: n == 3, erratum="known")
    n = None if method == "free" else 3
    fin = lambda v, c=holds, variant=None, msg="": runner._finish(_result(v, method, msg, n), c, variant).expected
    assert fin("undecided") and fin("undecided", erratum)
    assert not fin("inconclusive") and not fin("error") and not fin("inconclusive", erratum)
    if method != "free":
        assert fin("proved") and fin("checked") and fin("numeric")
        assert not fin("fails")
        assert fin("fails", erratum) and not fin("checked", erratum)
        assert not fin("fails", erratum, "a correction") and fin("checked", erratum, "a correction")
    else:
        assert fin("proved")


def test_a_method_that_does_not_apply_is_undecided_and_expected():
    res = runner._finish(_result("inconclusive", "float", "not applicable: no residuals"), _claim("c", _ok), None)
    assert res.verdict == "undecided" and res.expected


@needs_fork
def test_float_on_a_pure_rank_claim_is_undecided():
    c = _claim("rk", lambda s: {"rank": Rank(s.X, 1)}, sizes=admissible(n_max=2))
    res = runner.verify([c], sizes=[Size(2, 1)], methods=("float",))
    assert [(r.verdict, r.expected) for r in res] == [("undecided", True)]


# --------------------------------------------------------------------------- the command line

@needs_fork
def test_tricks_each_get_their_verdict_and_the_run_goes_on(run, tricks, monkeypatch):
    monkeypatch.setattr("stiefelsym.run.userfile.CLAIM_SECONDS", 2.0)    # the engine's tracing budget, not --timeout
    result = run("verify", "--claims", str(tricks), "--method", "modular", "--timeout", "2",
                 "--memory", "3", "--jobs", "2", "--format", "json")
    assert result.exit_code == 1, result.output
    payload = json.loads(result.stdout)                 # stdout is the document and nothing else
    by = {r["claim"]: r for r in payload["results"]}
    assert set(by) == set(TRICK_VERDICTS)
    for cid, (verdict, message, expected) in TRICK_VERDICTS.items():
        assert (by[cid]["verdict"], by[cid]["expected"]) == (verdict, expected), (cid, by[cid])
        assert message in by[cid]["message"], (cid, by[cid]["message"])
    assert "printed at import" in result.stderr
    assert payload["meta"]["timeout"] == 2 and payload["meta"]["jobs"] == 2
    assert "--timeout 2 --memory 3" in by["loops-forever"]["rerun"]


@needs_fork
def test_subprocess_json_stays_one_document_whatever_claims_print(tmp_path, tricks):
    (tmp_path / "printer.py").write_text(textwrap.dedent('''
        import atexit, os, sys, threading
        from stiefelsym import admissible, claim
        print("import")
        atexit.register(print, "at exit")
        atexit.register(os.write, 1, b"fd 1 at exit\\n")

        @claim("printer", paper="t", kind="id", section="9", sizes=admissible(n_max=2))
        def printer(s):
            print("body")
            os.write(1, b"fd 1 in the body\\n")
            return {"XtX": s.X.T @ s.X - s.Ir}
    '''))
    proc = stiefelsym("verify", "--claims", "printer.py", "--format", "json", "--no-report",
                      "--method", "modular", "--method", "float", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    payload = json.loads(proc.stdout)
    assert len(payload["results"]) == 6
    for text in ("import", "body", "fd 1 in the body"):
        assert text in proc.stderr
    # the file's exit handlers run nowhere since stop 83: it is imported only in children that each do one job and
    # end without running the exit handlers of what they imported; whatever they would print never reaches stdout
    assert "at exit" not in proc.stdout
    proc = stiefelsym("list", "--claims", "printer.py", cwd=tmp_path)
    assert proc.returncode == 0 and "import" not in proc.stdout and "import" in proc.stderr


@pytest.mark.parametrize("body, what", [
    ("raise SystemExit(0)", "SystemExit"),
    ("raise SystemExit('bye')", "SystemExit: bye"),
    ("class Out(BaseException): pass\nraise Out('x')", "Out: x"),
    ("raise RuntimeError('no')", "RuntimeError: no"),
])
def test_a_claims_file_that_raises_at_import_is_bad_input(run, tmp_path, body, what):
    (tmp_path / "bad.py").write_text("print('hello')\n" + body + "\n")
    result = run("verify", "--claims", "bad.py")
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert lines[-1].startswith("stiefelsym verify: error: bad.py: ") and what in lines[-1]
    assert [line for line in lines if "error" in line] == [lines[-1]]
    assert result.stdout == ""


def test_subprocess_claims_file_exiting_at_import_exits_2(tmp_path):
    (tmp_path / "bye.py").write_text("import sys\nsys.exit(0)\n")
    proc = stiefelsym("verify", "--claims", "bye.py", cwd=tmp_path)
    assert proc.returncode == 2
    assert proc.stdout == "" and len(proc.stderr.strip().splitlines()) == 1
    assert "bye.py: SystemExit" in proc.stderr


SLOW = textwrap.dedent('''
    import os, subprocess, sys, time
    from pathlib import Path
    from stiefelsym import admissible, claim

    @claim("slow", paper="t", kind="id", section="9", sizes=admissible(n_max=1))
    def slow(s):
        child = subprocess.Popen(["sleep", "300"])
        Path("pids.tmp").write_text(f"{os.getpid()} {child.pid}")
        os.replace("pids.tmp", "pids")
        time.sleep(300)
        return {"XtX": s.X.T @ s.X - s.Ir}
''')


def _gone(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    try:   # a zombie waiting for a parent that will not reap it is gone too
        return Path(f"/proc/{pid}/stat").read_text().split(")")[-1].split()[0] == "Z"
    except OSError:
        return True


@needs_fork
@pytest.mark.parametrize("sig, status, word", [(signal.SIGTERM, 143, "terminated"),
                                               (signal.SIGINT, 130, "interrupted")])
def test_subprocess_signal_kills_every_worker_and_writes_no_report(tmp_path, sig, status, word):
    (tmp_path / "slow.py").write_text(SLOW)
    proc = subprocess.Popen([sys.executable, "-m", "stiefelsym", "verify", "--claims", "slow.py",
                             "--method", "modular", "--report-dir", "out", "--timeout", "120"],
                            # the plain spawn: the file tells the test its pids through its working directory
                            cwd=tmp_path, env=dict(_env(), STIEFELSYM_CONFINE="spawn"), stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            # as from an interactive shell: a background test run inherits SIGINT ignored
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        deadline = time.monotonic() + 60
        while not (tmp_path / "pids").exists():
            assert proc.poll() is None, proc.communicate()
            assert time.monotonic() < deadline, "the slow claim never started"
            time.sleep(0.05)
        pids = [int(p) for p in (tmp_path / "pids").read_text().split()]
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == status, err
    assert "Traceback" not in err
    # the claims file is traced in child processes before the plan is made (no code of it runs in the CLI)
    assert err.strip().splitlines()[-1] in (f"stiefelsym: {word} after 0 of 1 runs; no report written",
                                            f"stiefelsym: {word} after 0 of ? runs (while tracing the claims "
                                            "files); no report written")
    assert not (tmp_path / "out").exists()
    deadline = time.monotonic() + 10
    while not all(_gone(p) for p in pids) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert all(_gone(p) for p in pids), pids


# --------------------------------------------------------------------------- lines, legend, help

def test_result_lines_give_the_witness_or_the_reason():
    r = _result("fails")
    r.witness = {"entry": "prep[1,2]", "value": "3/7"}
    assert r.line().endswith("-- witness prep[1,2] = 3/7")
    r = _result("fails")
    r.certificate = "invariant forms: rank 3 (paper: 2)"
    assert r.line().endswith("-- invariant forms: rank 3 (paper: 2)")
    for verdict in ("undecided", "inconclusive", "error"):
        r = _result(verdict, message="the reason\n  on two lines " + "x" * 300)
        assert " -- the reason on two lines xxx" in r.line() and r.line().endswith("...")
        assert r.reason(None).endswith("x" * 300)
    assert " -- " not in _result("checked").line()
    # auto ran the exact method first (its time is in the record's): the line says why it went on, unless the
    # size was above the claim's symbolic budget (no attempt was made)
    tried = _result("checked", message="exact: the symbolic attempt ended without a verdict: out of memory; "
                                       "2 independent points")
    assert tried.line().endswith("-- after exact: the symbolic attempt ended without a verdict: out of memory")
    skipped = _result("checked", message="exact: (6,3) is above this claim's symbolic budget (n <= 5); 2 points")
    assert " -- " not in skipped.line()


@needs_fork
def test_cli_prints_reasons_rerun_and_the_legend(run, tricks, monkeypatch):
    monkeypatch.setattr("stiefelsym.run.userfile.CLAIM_SECONDS", 2.0)    # the engine's tracing budget, not --timeout
    result = run("verify", "good", "loops-forever", "--claims", str(tricks), "--method", "modular",
                 "--timeout", "2")
    assert result.exit_code == 1
    lines = result.stdout.splitlines()
    i = next(i for i, line in enumerate(lines) if line.startswith("loops-forever (1,1) modular"))
    # (it loops at every size: its tracing with symbolic sizes ran out of time, and it is traced at no size)
    assert "UNEXPECTED -- exceeded its time budget before it was traced at (1,1)" in lines[i]
    # the whole reason on the next line: the engine's tracing budget, which is not --timeout
    assert "its tracing with symbolic sizes" in lines[i + 1] and "budget is not --timeout" in lines[i + 1]
    assert "tracing budget of 2 s per function and size" in lines[i + 1]
    assert lines[i + 2] == (f"  rerun: stiefelsym verify loops-forever --size 1,1 --method modular --seed 0 "
                            f"--claims {tricks} --timeout 2")
    assert any(line.startswith("p<=: the Schwartz-Zippel bound") for line in lines)


def test_verify_help_explains_p_and_the_budgets(run):
    result = run("verify", "--help")
    assert result.exit_code == 0
    text = " ".join(result.stdout.split())
    assert "Schwartz-Zippel false-pass bound" in text
    assert "cost model" in text and "--budget" in text
    for option in ("--timeout SECONDS", "--memory GIB", "--jobs N", "--budget"):
        assert option in text


# --------------------------------------------------------------------------- report files, --claims, mutate

def test_report_files_respect_the_umask(tmp_path):
    for mask, mode in ((0o022, 0o644), (0o077, 0o600), (0o002, 0o664)):
        old = os.umask(mask)
        try:
            write_atomic(tmp_path / f"r{mask}.json", "{}")
        finally:
            os.umask(old)
        assert (tmp_path / f"r{mask}.json").stat().st_mode & 0o777 == mode


@pytest.mark.parametrize("args", [["verify", "--report-dir", ""], ["verify", "--report-dir", "  "],
                                  ["report", "--report-dir", ""]])
def test_empty_report_dir_is_refused(run, tmp_path, args):
    result = run(*args)
    assert result.exit_code == 2 and "report directory is empty" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def _claims_file(path: Path, *ids: str) -> None:
    path.write_text("from stiefelsym import admissible, claim\n" + "".join(
        f"@claim({cid!r}, paper='t', kind='id', section='9', sizes=admissible(n_max=1))\n"
        f"def c{i}(s):\n    return {{'XtX': s.X.T @ s.X - s.Ir}}\n" for i, cid in enumerate(ids)))


@needs_fork
def test_claims_given_twice_loads_both_files(run, tmp_path):
    _claims_file(tmp_path / "a.py", "from-a")
    _claims_file(tmp_path / "b.py", "from-b", "also-b")
    result = run("verify", "--claims", "a.py", "--claims", "b.py", "--method", "modular",
                 "--format", "json", "--report-dir", "out")
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    assert [r["claim"] for r in payload["results"]] == ["from-a", "from-b", "also-b"]
    assert payload["meta"]["command"].startswith("stiefelsym verify --claims a.py --claims b.py")
    assert payload["meta"]["title"] == "Verification of the claims of a.py, b.py"
    assert payload["results"][1]["rerun"].endswith("--claims b.py")
    _, results = load_results(tmp_path / "out" / "results.json")
    assert len(results) == 3


def test_an_id_defined_in_two_claims_files_is_refused(run, tmp_path):
    _claims_file(tmp_path / "a.py", "same")
    _claims_file(tmp_path / "b.py", "other", "same")
    result = run("verify", "--claims", "a.py", "--claims", "b.py")
    assert result.exit_code == 2
    assert "claim 'same' is defined in both a.py and b.py" in result.stderr


def test_mutate_is_loaded_only_when_asked_for(run, monkeypatch, tmp_path):
    monkeypatch.setattr(cli.main, "commands", {k: v for k, v in cli.main.commands.items() if k != "mutate"})
    monkeypatch.setattr(cli.main, "lazy", {"mutate": ("stiefelsym_no_such_module", "mutate")})
    assert run("--help").exit_code == 0 and "mutate" not in run("--help").stdout
    assert run("mutate").exit_code == 2
    (tmp_path / "fake_mutate.py").write_text(
        "import click\n@click.command()\ndef mutate():\n    'Mutation analysis.'\n    click.echo('mutating')\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(cli.main, "lazy", {"mutate": ("fake_mutate", "mutate")})
    assert "fake_mutate" not in sys.modules
    assert run("list", "--claims", "nothing.py").exit_code == 2 and "fake_mutate" not in sys.modules
    result = run("mutate")
    assert result.exit_code == 0 and result.stdout == "mutating\n"


def test_list_does_not_import_the_mutate_command(tmp_path):
    code = ("import sys\nfrom stiefelsym.cli import main\n"
            "code = main(['list'], standalone_mode=False)\n"
            "print('MUTATE-LOADED' if 'stiefelsym.cli.mutate' in sys.modules else 'MUTATE-NOT-LOADED',"
            " file=sys.stderr)\n")
    proc = subprocess.run([sys.executable, "-c", code], cwd=Path(__file__).resolve().parents[1], env=_env(),
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "MUTATE-NOT-LOADED" in proc.stderr


def test_without_fork_the_plan_runs_in_process():
    claims = [_claim("exits", _exits), _claim("ok", _ok), _count_claim()]
    results = runner.verify(claims, methods=("auto", "modular"), fork=False)
    by = {(r.claim, r.variant, r.n, r.method): r for r in results}
    assert by[("exits", None, 1, "auto")].verdict == "error"
    assert "SystemExit" in by[("exits", None, 1, "auto")].message
    assert by[("ok", None, 1, "modular")].verdict == "checked"
    assert by[("count", "counted right", 3, "modular")].verdict == "proved"
    with_fork = runner.verify(claims, methods=("auto", "modular")) if hasattr(os, "fork") else results
    assert [(r.claim, r.variant, r.n, r.r, r.method, r.verdict) for r in results] == \
        [(r.claim, r.variant, r.n, r.r, r.method, r.verdict) for r in with_fork]


def test_only_a_documented_erratum_is_expected_to_fail(run, tmp_path):
    (tmp_path / "undocumented.py").write_text(
        "from stiefelsym import admissible, claim\n"
        "@claim('u', paper='t', kind='id', section='9', sizes=admissible(n_max=1), fails_at=lambda n, r: True)\n"
        "def u(s):\n    return {'XtX': s.X.T @ s.X}\n")
    result = run("verify", "--claims", "undocumented.py")
    assert result.exit_code == 2 and "must be a documented erratum" in result.stderr
    c = _claim("c", _ok)
    object.__setattr__(c, "fails_at", lambda n, r: True)   # forced in afterwards, still without an erratum
    assert not runner._finish(_result("fails"), c, None).expected
    assert runner._finish(_result("checked"), c, None).expected


def test_an_erratum_predicate_that_breaks_is_an_error_not_a_crash():
    c = _claim("c", _ok, fails_at=lambda n, r: 1 / 0, erratum="broken predicate")
    res = runner._finish(_result("fails"), c, None)
    assert res.verdict == "error" and not res.expected and "ZeroDivisionError" in res.message


# --------------------------------------------------------------------------- heavy symbolic attempts in workers

def _falsely_orthonormal(s):
    return {"XtX = 2 I": s.X.T @ s.X - 2 * s.Ir}


def _hoard(*args, **kwargs):
    """Stands for a symbolic attempt that exhausts the memory budget (Python's allocator)."""
    hoard = []
    while True:
        hoard.append(bytes(1 << 28))


def _abort(*args, **kwargs):
    """Stands for flint aborting when a native allocation fails under the memory budget."""
    import faulthandler
    faulthandler.disable()          # (pytest's dump of the aborting child would only be noise)
    os.write(1, FLINT_WORDS)     # what flint prints before it aborts, on the standard output
    os.abort()


FLINT_WORDS = b"FLINT exception (General error):\n    Unable to allocate memory (325691264).\n"


def _attempt_in_a_worker(task):
    from stiefelsym.methods.fixed_size import run_exact_isolated
    res = run_exact_isolated(_claim("ok", _ok, sizes=admissible(n_max=6)), 6, 2, 0, time_budget=20,
                             in_worker=True)
    return os.getpid(), res.verdict, res.message


@needs_fork
def test_small_symbolic_attempts_stay_in_the_worker_and_heavy_ones_are_forked():
    from stiefelsym.methods import fixed_size as methods
    ok = _claim("ok", _ok, sizes=admissible(n_max=6))
    assert not methods.isolates(ok, 1, 1, in_worker=True)
    assert methods.isolates(ok, 2, 1, in_worker=True) and methods.isolates(ok, 3, 2, in_worker=True)   # a user's, from n = 2
    assert methods.isolates(ok, 4, 2, in_worker=True)     # a claim the cost model never measured (a user's)
    assert methods.isolates(ok, methods.ISOLATE_MIN_N, 2, in_worker=True)
    from stiefelsym.claims import load_catalog
    small = load_catalog().get("euclidean-flow")           # measured, and predicted small at (4,2)
    assert not methods.isolates(small, 4, 2, in_worker=True)
    assert methods.isolates(ok, 4, 2) and not methods.isolates(ok, 3, 2)   # outside a worker: the hard time limit


@needs_fork
def test_the_mutants_of_a_costly_claim_have_their_symbolic_runs_forked():
    """In the mutation analysis the symbolic runs at n <= 4 stay in the process (thousands of small runs), except
    the mutants' of a claim whose own symbolic run took MUTANT_ISOLATE_SECONDS there: a mutant can cost far more,
    and one flint product is out of reach of the signal-based limit, not of a kill."""
    from stiefelsym.methods import fixed_size as methods
    ok = _claim("ok", _ok, sizes=admissible(n_max=6))
    loan = methods.PointLoan(exact_seconds=30)
    with methods.lending_points(loan):
        loan.recording = True
        printed = methods.run_exact_isolated(ok, 3, 2, 0)
        loan.recording = False
        assert loan.exact_cost[("ok", 3, 2)] == printed.seconds
        assert not methods.isolates(ok, 3, 2) and not methods.isolates(ok, 4, 2) and methods.isolates(ok, 5, 2)
        loan.exact_cost[("ok", 3, 2)] = methods.MUTANT_ISOLATE_SECONDS
        assert methods.isolates(ok, 3, 2)
        forked = methods.run_exact_isolated(ok, 3, 2, 0)
        assert (forked.verdict, forked.certificate) == (printed.verdict, printed.certificate)
        loan.forget("ok")
        assert not loan.exact_cost


@needs_fork
def test_a_measured_small_attempt_stays_in_the_worker_unless_its_memory_or_size_is_beyond_the_model(monkeypatch):
    from stiefelsym.claims import load_catalog
    from stiefelsym.methods import costmodel, fixed_size as methods
    small = load_catalog().get("euclidean-flow")
    n = methods.ISOLATE_MIN_N
    assert costmodel.predict("exact", small, n, 2) < methods.ISOLATE_SECONDS
    monkeypatch.setattr(methods, "_memory_budget", lambda: float(4 * GIB))
    assert not methods.isolates(small, n, 2, in_worker=True)     # no fork for a run of milliseconds
    # the same run where its predicted peak memory is a large part of the budget: forked
    peak = costmodel.model().predict_memory("exact", small, n, 2)
    monkeypatch.setattr(methods, "_memory_budget", lambda: peak / methods.ISOLATE_MEMORY_FRACTION / 2)
    assert methods.isolates(small, n, 2, in_worker=True)
    assert not methods.isolates(small, n - 2, 2, in_worker=True)   # below ISOLATE_MIN_N memory is not asked
    # beyond every size the model measured the symbolic method at: forked, whatever it predicts
    monkeypatch.setattr(methods, "_memory_budget", lambda: float(1 << 60))
    top = max(costmodel.model().measured["exact"].values())
    assert methods.isolates(small, top + 1, 1, in_worker=True)
    # and a forked attempt gives the record an attempt in the worker gives
    monkeypatch.setattr(methods, "_memory_budget", lambda: float(4 * GIB))
    here = methods.run_exact_isolated(small, n, 2, 0, in_worker=True)
    monkeypatch.setattr(methods, "_memory_budget", lambda: 1.0)
    forked = methods.run_exact_isolated(small, n, 2, 0, in_worker=True)
    assert (here.verdict, here.message, here.digest) == (forked.verdict, forked.message, forked.digest)
    assert here.verdict in ("proved", "checked")


@needs_fork
@pytest.mark.parametrize("dies", [_hoard, _abort], ids=["MemoryError", "SIGABRT"])
def test_a_symbolic_attempt_that_exceeds_memory_in_a_worker_leaves_the_worker_alive(monkeypatch, dies):
    from stiefelsym.methods import fixed_size as methods
    monkeypatch.setattr(methods, "run_exact", dies)
    with WorkerPool(_attempt_in_a_worker, workers=1, timeout=60, memory=3 * GIB) as pool:
        outcomes = [o for _, o in pool.run(["first", "second"])]
    assert [o.kind for o in outcomes] == ["ok", "ok"]
    (pid1, verdict1, message1), (pid2, verdict2, message2) = (o.value for o in outcomes)
    assert pid1 == pid2                         # the same worker ran both: it survived the first
    assert verdict1 == verdict2 == "inconclusive"
    assert message1.startswith("the symbolic attempt ended without a verdict: the child process ")
    assert ("ran out of memory" if dies is _hoard else "killed by SIGABRT") in message1
    if dies is _abort:      # flint's words are in the record, not printed raw on the run's standard error
        assert message1.endswith("its last words: Unable to allocate memory (325691264).)")


@needs_fork
@pytest.mark.parametrize("dies", [_hoard, _abort], ids=["MemoryError", "SIGABRT"])
def test_auto_falls_back_to_modular_when_the_symbolic_attempt_dies(monkeypatch, dies):
    from stiefelsym.methods import fixed_size as methods
    from stiefelsym.methods import specialise
    monkeypatch.setattr(methods, "run_exact", dies)
    # (where the dimension-free method has no proof of the claim's graph: with one, auto would take it)
    monkeypatch.setattr(specialise, "specialised", lambda *a, **kw: None)
    claims = [_claim("ok", _ok, sizes=admissible(n_max=6)), _claim("false", _falsely_orthonormal,
                                                                    sizes=admissible(n_max=6))]
    res = runner.verify(claims, sizes=[Size(6, 2)], methods=("auto",), timeout=60, memory=3, seed=0)
    by = {r.claim: r for r in res}
    assert by["ok"].method == "modular" and by["ok"].verdict == "checked" and by["ok"].expected
    assert by["ok"].message.startswith("exact: the symbolic attempt ended without a verdict: the child process ")
    assert by["false"].verdict == "fails" and not by["false"].expected


@needs_fork
def test_a_forked_symbolic_attempt_in_a_worker_still_proves_and_refutes():
    claims = [_claim("ok", _ok, sizes=admissible(n_max=6)), _claim("false", _falsely_orthonormal,
                                                                    sizes=admissible(n_max=6))]
    res = runner.verify(claims, sizes=[Size(6, 2)], methods=("exact",), timeout=60, seed=0)
    by = {r.claim: r for r in res}
    assert by["ok"].verdict == "proved" and by["ok"].expected
    assert by["false"].verdict == "fails" and not by["false"].expected


# --------------------------------------------------------------------------- a symbolic budget in n and r

def test_auto_tries_the_symbolic_method_within_the_budget_in_r():
    kw = dict(sizes=admissible(n_max=3), exact_max_n=2, exact_max_r=((3, 2),))
    claims = [_claim("ok", _ok, **kw), _claim("false", _falsely_orthonormal, **kw)]
    res = runner.verify(claims, sizes=[Size(3, 2), Size(3, 3)], methods=("auto",), seed=0)
    by = {(r.claim, r.n, r.r): r for r in res}
    assert (by["ok", 3, 2].method, by["ok", 3, 2].verdict) == ("exact", "proved")
    assert (by["false", 3, 2].method, by["false", 3, 2].verdict) == ("exact", "fails")
    # above the budget: the dimension-free proof of the same graph, specialised (the modular method
    # where there is none)
    assert (by["ok", 3, 3].method, by["ok", 3, 3].verdict) == ("exact", "proved")
    assert by["ok", 3, 3].reductions[0].startswith("the dimension-free proof, specialised")
    assert by["false", 3, 3].verdict == "fails" and by["false", 3, 3].method == "modular"
    assert by["false", 3, 3].message.startswith("exact: (3,3) is above this claim's symbolic budget "
                                                "(n <= 2; r <= 2 at n = 3)")


@pytest.mark.parametrize("pairs", [((2, 1),), ((4, 5),), ((4, 0),), (("4", 2),), ((4,),)])
def test_a_budget_in_r_is_given_at_sizes_above_exact_max_n(pairs):
    with pytest.raises(ValueError, match="exact_max_r"):
        _claim("c", _ok, exact_max_n=3, exact_max_r=pairs)


def _printed_twice_the_identity(s):
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}


def _corrected_identity(s):
    return {"XtX": s.X.T @ s.X - s.Ir}


def _corrected_but_false(s):
    return {"XtX": s.X.T @ s.X - s.Ir + s.X.T @ s.P}


def test_a_correction_widens_the_symbolic_budget_of_the_corrected_statement_alone():
    """A correction's exact_max_r: auto proves the corrected statement symbolically where the printed one
    (above its budget) is refuted by a modular witness, refutes a false correction with the same budget
    symbolically, and leaves a correction without one to the modular method."""
    c = _claim("printed", _printed_twice_the_identity, sizes=admissible(n_max=3), exact_max_n=2,
               fails_at=lambda n, r: True, erratum="X^T X is I_r, not 2 I_r.")
    c.correction("I_r in place of 2 I_r", exact_max_r={3: 2})(_corrected_identity)
    c.correction("I_r and a term X^T P", exact_max_r={3: 3})(_corrected_but_false)
    c.correction("I_r in place of 2 I_r, no budget of its own")(_corrected_identity)
    assert not c.exact_at(3, 2) and c.corrected(0).exact_at(3, 2) and not c.corrected(0).exact_at(3, 3)
    assert c.corrected(2) is c and c.corrected(0).expect == c.expect
    res = runner.verify([c], sizes=[Size(3, 2), Size(3, 3)], methods=("auto",), seed=0)
    by = {(r.variant, r.n, r.r): r for r in res}
    printed, good, false, plain = (None, *(k.description for k in c.corrections))
    assert (by[printed, 3, 2].method, by[printed, 3, 2].verdict) == ("modular", "fails")
    assert (by[good, 3, 2].method, by[good, 3, 2].verdict) == ("exact", "proved")
    # above every budget: the dimension-free proof of the corrected statement, specialised
    assert (by[good, 3, 3].method, by[good, 3, 3].verdict) == ("exact", "proved")
    assert (by[false, 3, 2].method, by[false, 3, 2].verdict) == ("exact", "fails")
    assert (by[false, 3, 3].method, by[false, 3, 3].verdict) == ("exact", "fails")
    assert (by[plain, 3, 2].method, by[plain, 3, 2].verdict) == ("exact", "proved")
    assert by[plain, 3, 2].reductions[0].startswith("the dimension-free proof, specialised")


@pytest.mark.parametrize("pairs", [{2: 1}, {4: 5}, {3: 0}])
def test_a_correction_budget_in_r_is_given_at_sizes_above_the_claims_exact_max_n(pairs):
    c = _claim("printed", _printed_twice_the_identity, sizes=admissible(n_max=3), exact_max_n=2,
               fails_at=lambda n, r: True, erratum="X^T X is I_r, not 2 I_r.")
    with pytest.raises(ValueError, match="exact_max_r"):
        c.correction("I_r in place of 2 I_r", exact_max_r=pairs)


def test_a_correction_budget_reaches_a_claims_file(tmp_path):
    from stiefelsym.api import load
    path = tmp_path / "budget.py"
    path.write_text("from stiefelsym import admissible, claim\n"
                    "@claim('c', paper='t', kind='id', section='9', sizes=admissible(n_max=5), exact_max_n=4,\n"
                    "       fails_at=lambda n, r: True, erratum='X^T X is I_r, not 2 I_r.')\n"
                    "def c(s):\n    return {'XtX': s.X.T @ s.X - 2 * s.Ir}\n"
                    "@c.claim.correction('I_r in place of 2 I_r', exact_max_r={5: 3})\n"
                    "def c_corrected(s):\n    return {'XtX': s.X.T @ s.X - s.Ir}\n")
    c = load([path], catalog=False).get("c")
    assert c.corrections[0].exact_max_r == ((5, 3),) and not c.exact_at(5, 3)
    assert c.corrected(0).exact_at(5, 3) and not c.corrected(0).exact_at(5, 4)
    from click.testing import CliRunner
    out = CliRunner().invoke(cli.main, ["show", "--claims", str(path), "c"]).output
    assert "correction:  I_r in place of 2 I_r; exact symbolic method also up to r = 3 at n = 5" in out


def test_a_budget_in_r_reaches_a_claims_file(tmp_path):
    from stiefelsym.api import load
    path = tmp_path / "budget.py"
    path.write_text("from stiefelsym import admissible, claim\n"
                    "@claim('c', paper='t', kind='id', section='9', sizes=admissible(n_max=5), exact_max_n=4,\n"
                    "       exact_max_r={5: 3})\n"
                    "def c(s):\n    return {'XtX': s.X.T @ s.X - s.Ir}\n")
    c = load([path], catalog=False).get("c")
    assert c.exact_max_r == ((5, 3),) and c.exact_at(5, 3) and not c.exact_at(5, 4) and c.exact_at(4, 4)


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/status") as f:
            return not any(line.startswith("State:") and ("Z" in line or "X" in line) for line in f)
    except FileNotFoundError:
        return False


@needs_fork
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="PR_SET_PDEATHSIG is Linux's")
def test_an_isolated_attempt_dies_with_the_process_that_forked_it():
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:       # stands for a worker (or the command line) killed while its attempt runs
        try:
            os.close(r)
            from stiefelsym.run.isolate import run_isolated

            def attempt():
                os.write(w, f"{os.getpid()}\n".encode())
                time.sleep(60)
            run_isolated(attempt, 60, str)
        finally:
            os._exit(0)
    os.close(w)
    with os.fdopen(r) as f:
        child = int(f.readline())
    os.kill(pid, signal.SIGKILL)
    os.waitpid(pid, 0)
    deadline = time.monotonic() + 10
    while _alive(child) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _alive(child)


def _abort_job(task):
    _abort()


@needs_fork
def test_a_worker_killed_by_sigabrt_is_said_to_have_aborted_as_flint_does():
    """A worker that dies by SIGABRT (flint's answer to a failed allocation) is reported with that reading of the
    signal, as the isolated symbolic attempt is."""
    with WorkerPool(_abort_job, workers=1, timeout=60, memory=3 * GIB) as pool:
        (outcome,) = [o for _, o in pool.run(["only"])]
    assert outcome.kind == "died", outcome
    assert "killed by SIGABRT; a native library aborted, as flint does" in outcome.message, outcome.message


@needs_fork
def test_an_isolated_child_s_standard_error_is_passed_on_when_it_answers(capfd):
    from stiefelsym.run.isolate import run_isolated

    def speaks():
        print("a line of the claim", file=sys.stderr)
        return 7
    assert run_isolated(speaks, 30, str) == 7
    assert "a line of the claim" in capfd.readouterr().err


@needs_fork
def test_flint_running_out_of_memory_in_a_forked_attempt_prints_nothing_raw(tmp_path):
    """flint says why it aborts on the standard output: the words go into the record, not to the terminal."""
    script = tmp_path / "oom.py"
    script.write_text(
        "import resource, flint\n"
        "resource.setrlimit(resource.RLIMIT_AS, (600 << 20, 600 << 20))\n"
        "from stiefelsym.run.isolate import run_isolated, ChildDied\n"
        "def grow():\n"
        "    x = flint.fmpz_poly([1] * 1000)\n"
        "    for _ in range(30):\n"
        "        x = x * x\n"
        "try:\n"
        "    run_isolated(grow, 60, repr)\n"
        "except ChildDied as exc:\n"
        "    open('said.txt', 'w').write(str(exc))\n")
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}
    proc = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=120, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0 and proc.stdout == "" and proc.stderr == "", (proc.stdout, proc.stderr)
    said = (tmp_path / "said.txt").read_text()
    assert said.startswith("the child process died (killed by SIGABRT") and "Unable to allocate memory" in said


@needs_fork
def test_a_forked_attempt_prints_what_it_printed_once_and_the_parent_s_pending_output_once(tmp_path):
    """Output the parent had not yet written when it forked is written by the parent alone, and what the child
    printed (Python's buffers, which os._exit does not flush) reaches the parent's standard output, in order."""
    script = tmp_path / "prints.py"
    script.write_text(
        "import sys\n"
        "from stiefelsym.run.isolate import run_isolated\n"
        "def child():\n"
        "    print('B', end='')\n"
        "    return 1\n"
        "print('A', end='')\n"
        "assert run_isolated(child, 60, repr) == 1\n"
        "print('C')\n")
    # buffered, as a pipe is by default (before: "AAC", the parent's "A" written twice and the child's "B" lost)
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST") and k != "PYTHONUNBUFFERED"}
    proc = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=120, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == "ABC\n", proc.stdout


def _spin():
    while True:
        pass


def _nap():
    time.sleep(1.5)
    return "rested"


def test_a_cpu_limit_stops_a_computation_by_its_cpu_time_not_by_the_wall_clock():
    """The dimension-free attempt of a run at a size is limited in CPU time (RLIMIT_CPU in its child), so whether
    it ends in time is the computation's, not the load of the machine: a child that computes is stopped after
    its CPU seconds (HardTimeout, as the wall limit), one that waits longer than that without computing is not."""
    from stiefelsym.run.isolate import HardTimeout, run_isolated
    t0 = time.monotonic()
    with pytest.raises(HardTimeout):
        run_isolated(_spin, 60, str, cpu_seconds=1)
    assert time.monotonic() - t0 < 30
    assert run_isolated(_nap, 20, str, cpu_seconds=1) == "rested"


def test_a_cpu_deadline_counts_cpu_time_and_nests_with_a_wall_deadline():
    """deadline(..., cpu=True) (the engine's rank routes) stops a computation by its CPU seconds: waiting does
    not count, computing does; inside a wall-clock deadline, leaving it restores the outer one untouched."""
    import signal as _sig
    from stiefelsym.claims import ClaimTimeout, deadline
    with deadline(30, "outer"):
        outer = _sig.getitimer(_sig.ITIMER_REAL)[0]
        with deadline(0.3, "waiting", cpu=True):
            time.sleep(0.6)            # no CPU time: not stopped
        with pytest.raises(ClaimTimeout, match="of CPU time"):
            with deadline(0.3, "spinning", cpu=True):
                while True:
                    pass
        assert 0 < _sig.getitimer(_sig.ITIMER_REAL)[0] <= outer
        assert _sig.getitimer(_sig.ITIMER_PROF)[0] == 0
    assert _sig.getitimer(_sig.ITIMER_REAL)[0] == 0
