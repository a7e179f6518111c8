"""A user's claims file runs in child processes only (stiefelsym.run.userfile): what comes back is pure data."""
import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

from stiefelsym.ir.graph import Named, Ref, Size
from stiefelsym.run import userfile
from stiefelsym.run.userfile import NoGraph, WireError, _enc, _loads, _value, load_claims_isolated

ROOT = Path(__file__).resolve().parents[1]
ADV = ROOT / "tests" / "adversary"


def test_module_code_of_a_claims_file_never_runs_in_the_cli_process(tmp_path):
    """The file runs in a spawned interpreter: not the CLI's process, none of the run's environment, and its
    parent's command line is not the run's (in namespaces it has no parent it can see)."""
    env = dict(os.environ, STIEFELSYM_TEST_PID_FILE="marker-of-the-run")
    p = subprocess.Popen([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(ADV / "module_code_pid.py"),
                          "--method", "modular", "--size", "3,2", "--report-dir", str(tmp_path)],
                         cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    out, err = p.communicate(timeout=300)
    assert p.returncode == 0, out + err
    assert "adv-pid-orthonormal (3,2) modular: checked" in out, out + err
    seen = [line for line in err.splitlines() if line.startswith("claims-file-pid ")]
    assert seen, err
    for line in seen:
        pid = int(line.split()[1])
        assert pid != p.pid, (p.pid, line)
        assert "STIEFELSYM_TEST_PID_FILE" not in line and "marker-of-the-run" not in line, line
        assert "3,2" not in line and "modular" not in line and "--claims" not in line, line


def test_the_wire_decoder_gives_ir_values_only():
    for v in (None, True, 3, "x", (Ref(2), Size(2, "r", None), Named("a.b")), [Fraction(-3, 4), (1, "n")]):
        assert _value(_enc(v)) == v and type(_value(_enc(v))) is type(v)
    for bad in ({"f": [1, 0]}, {"s": [1, "m", None]}, {"x": 1}, {"r": -1}, {"t": [1], "l": []}, [1], 1.5):
        with pytest.raises(WireError):
            _value(bad)
    with pytest.raises(WireError):
        _loads(b'{"a": 1.0}')
    with pytest.raises(WireError):
        _loads(b'{"a": NaN}')


def test_claims_of_a_file_are_built_here_unreviewed_with_graphs_at_the_needed_sizes():
    from stiefelsym.ir import compile_claim
    from stiefelsym.scene import REALIZATIONS
    for c in load_claims_isolated(ADV / "reviewed_flag_spoofed.py", [(4, 2)]):
        assert c.reviewed is False
    (c,) = load_claims_isolated(ADV / "fixed_size_only.py", [(4, 2), (2, 3)])
    assert c.func.sizes() == [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (3, 3), (4, 2)]   # (2,3): no size
    cons = REALIZATIONS[c.realization]
    assert compile_claim(c.func, 4, 2, (cons.name, cons.build)).digest()
    with pytest.raises(Exception, match="needs fixed sizes"):
        compile_claim(c.func, None, None, (cons.name, cons.build))     # the refusal recorded in the child
    with pytest.raises(NoGraph, match="no graph at \\(5,2\\)"):
        compile_claim(c.func, 5, 2, (cons.name, cons.build))
    with pytest.raises(NoGraph):
        compile_claim(c.func, 3, 2, ("metric", cons.build))
    assert c.sizes.admits(3, 2) and c.sizes.admits(16, 16) and not c.sizes.admits(2, 3)


def test_a_claim_with_a_graph_of_symbolic_sizes_is_traced_in_the_child_at_no_size():
    """Its graph with symbolic sizes is its graph at every size: the child sends no graph for a size (none was
    traced with a number), and the size the command asks for gets that graph."""
    from stiefelsym.ir import _compiled_graph as compile_claim     # the engine's own graph (the public one copies)
    from stiefelsym.scene import REALIZATIONS
    for c in load_claims_isolated(ADV / "size_read_by_introspection.py", [(7, 2)]):
        assert c.func.sizes() == [], c.func.sizes()
        cons = REALIZATIONS[c.realization]
        free = compile_claim(c.func, None, None, (cons.name, cons.build))
        assert compile_claim(c.func, 7, 2, (cons.name, cons.build)) is free


def test_one_pipe_reader_for_the_tracer_and_the_isolated_child():
    """isolate.next_chunk is how both the tracer (its children's lines) and read_pipe wait: the bytes written,
    b"" once the writer closed its end, None when the deadline passes first (nothing is lost across calls)."""
    import os
    import time

    from stiefelsym.run.isolate import next_chunk, read_pipe

    r, w = os.pipe()
    os.write(w, b"one line\n")
    assert next_chunk(r, time.monotonic() + 5) == b"one line\n"
    t0 = time.monotonic()
    assert next_chunk(r, time.monotonic() + 0.2) is None and time.monotonic() - t0 >= 0.19
    os.write(w, b"after the timeout")
    os.close(w)
    assert next_chunk(r, time.monotonic() + 5) == b"after the timeout"
    assert next_chunk(r, time.monotonic() + 5) == b""
    os.close(r)
    r, w = os.pipe()
    failed = []
    assert read_pipe(r, 0.2, lambda: failed.append(True)) is None and failed == [True]
    os.close(w)
    r, w = os.pipe()
    os.write(w, b"all of it")
    os.close(w)
    assert read_pipe(r, 5, lambda: failed.append(False)) == b"all of it" and failed == [True]


_STUBBORN = '''from stiefelsym import admissible, claim


def stubborn(*args):
    while True:             # catches every alarm of the time limit, and goes on
        try:
            while True:
                pass
        except BaseException:
            continue


@claim("stubborn", paper=("prep",), kind="id", sizes=admissible(n_max=3{where}){fails_at})
def c(s):
    """XᵀP = 0 (false)."""
    return {{"c": s.X.T @ s.P}}
'''


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
def test_an_import_that_catches_its_time_limit_is_killed(tmp_path, monkeypatch):
    """A size statement evaluated at import that catches the import's alarm in a loop: the process that imports
    the file ends IMPORT_GRACE_SECONDS after the deadline (it ran until the file's hour was up).  (The end is
    _exit, not a kill to itself: the sandbox's interpreter is process 1 of its PID namespace, which ignores it.)"""
    import time
    from stiefelsym import claims
    path = tmp_path / "where_loop.py"
    path.write_text(_STUBBORN.format(where=", where=stubborn", fails_at=""), encoding="utf-8")
    monkeypatch.setattr(claims, "IMPORT_SECONDS", 0.3)
    monkeypatch.setattr(userfile, "IMPORT_GRACE_SECONDS", 0.3)
    t0 = time.monotonic()
    pid = os.fork()
    if pid == 0:
        try:
            userfile._import_bounded(str(path))
        finally:
            os._exit(0)
    _, status = os.waitpid(pid, 0)
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == userfile.IMPORT_EXIT
    assert time.monotonic() - t0 < 10


_HOLDS_THE_LOCK = '''from stiefelsym import admissible, claim

sum(range(10 ** 15))        # one call in C that holds the interpreter's lock: no alarm and no thread runs meanwhile


@claim("holds", paper=("prep",), kind="id", sizes=admissible(n_max=3))
def c(s):
    """XᵀP = 0 (false)."""
    return {"c": s.X.T @ s.P}
'''


def test_an_import_that_holds_the_interpreter_s_lock_in_c_is_killed_by_the_verifying_process(tmp_path, monkeypatch):
    """A file whose import holds the interpreter's lock in C stops the import's alarm and its watch thread alike:
    it ran until the file's hour (FILE_SECONDS) was up.  The verifying process waits for the line that ends the
    import and kills the interpreter when it has not come (here after 2 s instead of 160)."""
    from stiefelsym import claims
    monkeypatch.setattr(claims, "IMPORT_SECONDS", 1.0)
    _refused_soon(tmp_path / "holds_the_lock.py", _HOLDS_THE_LOCK, monkeypatch, "import outlived",
                  IMPORT_GRACE_SECONDS=0.5, IMPORT_START_SECONDS=0.5)


def _refused_soon(path, text, monkeypatch, match, **seconds):
    """The file ``text`` at ``path``, loaded with the deadlines of userfile set to ``seconds``, is refused (its
    message matches ``match``) within a minute."""
    import time
    from stiefelsym.claims import CatalogError
    path.write_text(text, encoding="utf-8")
    for name, value in seconds.items():
        monkeypatch.setattr(userfile, name, value)
    t0 = time.monotonic()
    with pytest.raises(CatalogError, match=match):
        userfile.load_claims_isolated(path)
    assert time.monotonic() - t0 < 60


_HOLDS_THE_LOCK_LATER = '''import threading
import time

from stiefelsym import admissible, claim


def _hold():
    time.sleep(0.3)
    sum(range(10 ** 15))    # once the import has ended: one call in C that holds the interpreter's lock


threading.Thread(target=_hold, daemon=True).start()


@claim("holds-later", paper=("prep",), kind="id", sizes=admissible(n_max=3))
def c(s):
    """XᵀX = I_r (true)."""
    time.sleep(0.5)
    return {"c": s.X.T @ s.X - s.Ir}
'''


def test_a_thread_of_the_file_that_holds_the_lock_while_the_claims_are_traced_is_killed(tmp_path, monkeypatch):
    """A thread the import starts, which takes the interpreter's lock in C once the import has ended, stopped the
    process that traces the claims (and its budgets) as well: the run waited for the file's hour.  The verifying
    process waits for a line after each function traced at a size, and kills the interpreter when none has come;
    and since every job imports the file in a child of its own (stop 83), the thread holds that child only, which
    the tracing process kills at the job's budget: the function is recorded as out of its tracing budget, and its
    run is `inconclusive`, within seconds."""
    import time
    from stiefelsym.claims import Size as At
    from stiefelsym.run.runner import run_one
    path = tmp_path / "holds_the_lock_later.py"
    path.write_text(_HOLDS_THE_LOCK_LATER, encoding="utf-8")
    for name in ("CLAIM_SECONDS", "META_SECONDS", "BEAT_GRACE_SECONDS"):
        monkeypatch.setattr(userfile, name, 1.0)
    t0 = time.monotonic()
    (c,) = userfile.load_claims_isolated(path, [(3, 2)])
    res = run_one(c, At(3, 2), "exact", 0)
    assert res.verdict == "inconclusive" and "time budget" in res.message, (res.verdict, res.message)
    assert time.monotonic() - t0 < 60


def test_the_deadlines_of_the_lines_read(monkeypatch):
    """_Lines: an import must end within ``seconds`` of the confinement line or of an answer; once it has, a BEAT
    line or more bytes must come within ``beat`` of the last; a marker split across chunks is one, a line that only
    starts like one is not, and a line of megabytes is read once (only a marker's length of it is kept)."""
    from stiefelsym.run import sandbox
    clock = [100.0]
    monkeypatch.setattr(sandbox.time, "monotonic", lambda: clock[0])
    lines = sandbox._Lines(10.0, 50.0)
    assert lines.deadline == float("inf")
    lines.read(b'{"confined": "namespaces"}\n')
    assert lines.deadline == 110.0                      # the import starts
    clock[0] = 105.0
    half = len(sandbox.IMPORTED) // 2
    lines.read(sandbox.IMPORTED[:half])
    assert lines.deadline == 110.0
    lines.read(sandbox.IMPORTED[half:])
    assert lines.deadline == 155.0                      # imported: the tracing's first job may take 50 s
    clock[0] = 150.0
    lines.read(sandbox.BEAT)
    assert lines.deadline == 200.0
    clock[0] = 190.0
    lines.read(sandbox.BEAT[:-1] + b"x" * (1 << 22))    # no marker: the start of a long answer line
    assert lines.deadline == 240.0 and len(lines.head) <= max(len(sandbox.IMPORTED), len(sandbox.BEAT))
    clock[0] = 230.0
    lines.read(b"y" * (1 << 20))
    assert lines.deadline == 280.0                      # more of it came
    lines.read(b"\n")
    assert lines.deadline == 240.0                      # an answer: the next import (second phase) starts
    lines.read(b"   \n")
    assert lines.deadline == 240.0                      # a blank line changes nothing


def test_the_import_lines_are_not_part_of_the_answer():
    """The interpreter's IMPORTED lines (one per import: the first phase's, each size's in the second) and BEAT
    lines (one per job traced) are taken out of what it answers, and only whole lines equal to a marker are."""
    from stiefelsym.run.sandbox import BEAT, IMPORTED, _answer
    assert _answer(IMPORTED + b'{"claims": []}') == b'{"claims": []}'
    assert _answer(IMPORTED + BEAT + BEAT + b'{"claims": []}') == b'{"claims": []}'
    two = IMPORTED + b'\n{"claims": [1]}\n' + IMPORTED + b'\n{"claims": [2]}\n'
    assert [x for x in _answer(two).split(b"\n") if x.strip()] == [b'{"claims": [1]}', b'{"claims": [2]}']
    inside = b'{"claims": ["{\\"imported\\": true}"]}'
    assert _answer(IMPORTED + inside) == inside


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
def test_erratum_sizes_that_catch_their_time_limit_end_at_the_metadata_budget(tmp_path, monkeypatch):
    """fails_at runs in the claim's metadata child, killed after META_SECONDS (it was CLAIM_SECONDS, 300 s)."""
    import time
    path = tmp_path / "fails_at_loop.py"
    path.write_text(_STUBBORN.format(where="", fails_at=", fails_at=stubborn, erratum=\"a loop\""), encoding="utf-8")
    ids = userfile._listed(str(path))["ids"]        # (this process never imports the file: each job does)
    monkeypatch.setattr(userfile, "META_SECONDS", 1.0)
    t0 = time.monotonic()
    with pytest.raises(ValueError, match="erratum sizes did not finish"):
        userfile._run_claim(str(path), ids, ids[0], None, 300.0, None)
    assert time.monotonic() - t0 < 10


def test_report_binds_a_user_s_records_to_the_graphs_of_the_file_named_now(run, tmp_path):
    """A results file is rendered with the claims file its meta names, relative to where report runs: another
    file of that name (or the file edited since) gave its claims other graphs, and report rendered the records
    under them.  Now each record of a user's claim is bound to its graph at its size, as check binds them."""
    claim = '''from stiefelsym import admissible, claim


@claim("twin", paper=("prep",), kind="id", sizes=admissible(n_max=3))
def twin(s):
    """The constraint XᵀP + PᵀX = 0 of T*V."""
    return {{"c": s.X.T @ s.P{rest}}}
'''
    (tmp_path / "mine.py").write_text(claim.format(rest=" + s.P.T @ s.X"), encoding="utf-8")
    made = run("verify", "--claims", "mine.py", "--size", "3,2", "--method", "modular", "--report-dir", "out")
    assert made.exit_code == 0, made.output
    assert run("report", "--results", "out/results.json").exit_code == 0
    (tmp_path / "mine.py").write_text(claim.format(rest=""), encoding="utf-8")     # XᵀP = 0: false
    again = run("report", "--results", "out/results.json")
    assert again.exit_code == 2 and "whose graph is not its claim's" in again.output, again.output


_WRITES_THE_MARK = '''import os, sys
from stiefelsym import admissible, claim

MARK = b'{{"imported": true}}\\n'
sys.stdout.write(MARK.decode())
sys.stdout.flush()
{forge}

@claim("fool-marker", paper=("prep",), kind="id", sizes=admissible(n_max=3))
def c(s):
    """X Xᵀ = I_n (false for r < n)."""
    return {{"c": s.X @ s.X.T - s.In}}
'''
_FORGE = '''for fd in range(3, 64):       # the end-line and a forged answer, on every descriptor the file can reach
    try:
        os.write(fd, MARK + b'{"claims": []}\\n')
    except OSError:
        pass
'''


def test_a_file_that_writes_the_import_s_end_line_itself_gets_no_other_graph(tmp_path):
    """The import's end-line (sandbox.IMPORTED) is the interpreter's; a file that prints it changes nothing, and one
    that writes it with a forged answer on every descriptor it reaches changes nothing either: a job holds only its
    own pipes since stop 85 (it broke the interpreter's answer before: bad input), and its lines that are not its
    job's answer are passed on as what it printed."""
    from stiefelsym.methods.fixed_size import run_points
    plain = tmp_path / "prints_the_mark.py"
    plain.write_text(_WRITES_THE_MARK.format(forge=""), encoding="utf-8")
    (c,) = userfile.load_claims_isolated(plain, [(3, 1)])
    assert run_points(c, 3, 1, "modular", 0).verdict == "fails"
    forged = tmp_path / "forges_the_answer.py"
    forged.write_text(_WRITES_THE_MARK.format(forge=_FORGE), encoding="utf-8")
    (c,) = userfile.load_claims_isolated(forged, [(3, 1)])
    assert run_points(c, 3, 1, "modular", 0).verdict == "fails"


_WRITES_THE_BEATS = '''import os
from stiefelsym import admissible, claim

for fd in range(3, 64):       # the progress and import lines, without an answer, on every descriptor it reaches
    try:
        os.write(fd, b'{"traced": true}\\n{"imported": true}\\n{"traced": true}\\n')
    except OSError:
        pass


@claim("forged-beats", paper=("prep",), kind="id", sizes=admissible(n_max=3))
def c(s):
    """XᵀP = 0 (false for r >= 2, true for r = 1, where XᵀP is skew 1 x 1)."""
    return {"c": s.X.T @ s.P}
'''


def test_a_file_that_writes_the_progress_lines_itself_gets_its_own_verdicts(tmp_path):
    """The tracing's progress line (sandbox.BEAT) written by the file itself, with the import's, on every descriptor
    it reaches: the lines are taken out of the answer, and the false claim fails under every fixed-size method
    where it is false and is proved only where it holds (r = 1)."""
    from stiefelsym.methods.fixed_size import run_exact_isolated, run_float, run_points
    path = tmp_path / "writes_the_beats.py"
    path.write_text(_WRITES_THE_BEATS, encoding="utf-8")
    (c,) = userfile.load_claims_isolated(path, [(3, 2), (3, 1)])
    assert run_exact_isolated(c, 3, 2, 0).verdict == "fails"
    assert run_points(c, 3, 2, "rational", 0).verdict == "fails"
    assert run_points(c, 3, 2, "modular", 0).verdict == "fails"
    assert run_float(c, 3, 2, 0).verdict == "fails"
    assert run_exact_isolated(c, 3, 1, 0).verdict == "proved"


STEP_FILE = '''
from stiefelsym import admissible, claim, twisted


@claim("u-magnetic-skew", kind="id", sizes=admissible(n_max=3, r_in=(2,)), section="A1")
def c(s):
    F = twisted.magnetic_matrix(s)
    return {"F + F^T": F + F.T}


@claim("u-magnetic-skew-wrong", kind="id", sizes=admissible(n_max=3, r_in=(2,)), section="A1")
def w(s):
    F = twisted.magnetic_matrix(s)
    return {"F - F^T": F - F.T}
'''

PROBE = '''
import sys
from stiefelsym.run.userfile import load_claims_isolated
from stiefelsym.methods.fixed_size import run_exact
before = "stiefelsym.twisted" in sys.modules
reg = load_claims_isolated(sys.argv[1], [(3, 2)])
loaded = "stiefelsym.twisted" in sys.modules
verdicts = [run_exact(reg.get(cid), 3, 2, 0).verdict for cid in ("u-magnetic-skew", "u-magnetic-skew-wrong")]
print(before, loaded, "stiefelsym.twisted" in sys.modules, *verdicts)
'''


def test_a_step_whose_module_this_process_has_not_imported_is_replayed(tmp_path):
    """The verifying process imports the module of an engine step a graph names (stiefelsym.twisted) when it
    replays the graph, not when it loads the file: a fresh interpreter that never imported it verifies the
    claim, and its corrupted twin fails."""
    f = tmp_path / "steps.py"
    f.write_text(STEP_FILE)
    out = subprocess.run([sys.executable, "-c", PROBE, str(f)], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["False", "False", "True", "proved", "fails"]


def test_a_graph_naming_what_is_not_an_engine_step_is_refused_and_imports_nothing():
    """The replay imports a module named by a graph only when it is one of the engine's: a name outside the
    engine (a library, the claims file's own module) is refused as before, and nothing is imported."""
    from stiefelsym.ir.replay import ReplayError, _registered
    from stiefelsym.ir.seal import engine_module_of
    assert engine_module_of("stiefelsym.twisted.at_point") == "stiefelsym.twisted"
    assert engine_module_of("os.system") is None
    assert engine_module_of("stiefelsym.cli.main") is None
    # a module of the package's folder that is not one of the fixed list (a file that appeared on disk after the
    # package was digested, s66/review/e2e_lazy_import.py) is never imported by a replay
    assert engine_module_of("stiefelsym.s66_new_module.step") is None
    assert engine_module_of("stiefelsym.backends.ball.BallField") is None
    for name in ("os.system", "antigravity.fly", "stiefelsym.cli.main", "stiefelsym.twisted.not_a_step"):
        before = set(sys.modules)
        with pytest.raises(ReplayError, match="not registered"):
            _registered(name)
        assert not {m for m in set(sys.modules) - before if not m.startswith("stiefelsym.twisted")}


REGISTERED = """
import sys
import stiefelsym.ir.replay
from stiefelsym.ir.seal import STEP_MODULES, import_engine
from stiefelsym.ir.trace import _NAMED
first = set(sys.modules)
import_engine()
for qual, _ in list(_NAMED.values()):
    owner = max((m for m in sys.modules if qual.startswith(m + ".")), key=len)
    if owner not in first and not any(qual.startswith(m + ".") for m in STEP_MODULES):
        print(qual)
print("done", len(_NAMED))
"""


def test_every_registered_step_is_in_a_module_the_replay_imports():
    """Each name an engine module registers (a step, a constant) belongs to a module of the fixed list
    STEP_MODULES or to one that the replay's own imports load: a graph that names it replays in a process that
    imported nothing else, and the list needs no module read off the disk."""
    out = subprocess.run([sys.executable, "-c", REGISTERED], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    lines = out.stdout.split("\n")
    assert lines[0].startswith("done") and int(lines[0].split()[1]) >= 27, out.stdout
