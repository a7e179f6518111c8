"""A claims file is traced in a spawned interpreter that knows nothing of the run (stiefelsym.run.sandbox): no
command line, no environment, no parsed options; in namespaces it sees no process of the run and writes
nowhere but a private /tmp.  Without namespaces (STIEFELSYM_CONFINE=spawn, or a platform without them) every
record of the file says so."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import uuid
from pathlib import Path

import pytest

from stiefelsym.run.sandbox import CONFINE_ENV, NOTES, SPAWN
from stiefelsym.run.userfile import load_claims_isolated

ROOT = Path(__file__).resolve().parents[1]
READ = ROOT / "tests" / "adversary" / "sandbox_run_read.py"
PASSING = ("proved", "checked", "numeric")
WAYS = ("parent", "processes", "environ", "objects", "argv")


def _namespaces() -> bool:
    from stiefelsym.run.sandbox import namespaces_available
    return namespaces_available()


NAMESPACES = pytest.mark.skipif(not _namespaces(), reason="no user + pid + mount namespaces here (unshare): the "
                                "file's interpreter is spawned without them, sees /proc and writes with the "
                                "user's rights (its records say so)")


def _env(confinement: str, **extra: str) -> dict:
    env = {k: v for k, v in os.environ.items() if k != CONFINE_ENV}
    if confinement == SPAWN:
        env[CONFINE_ENV] = SPAWN
    env.update(extra)
    return env


def _verify(claims: Path, *args: str, env: dict, report: Path) -> tuple[dict, subprocess.CompletedProcess]:
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(claims), *args, "--jobs", "1",
                          "--report-dir", str(report)], cwd=ROOT, env=env, capture_output=True, text=True,
                         timeout=600)
    recs = json.loads((report / "results.json").read_text())["results"] if (report / "results.json").exists() else []
    return {r["claim"]: r for r in recs}, out


@pytest.mark.parametrize("confinement", ["namespaces", SPAWN])
def test_a_file_that_looks_for_the_run_traces_one_graph_in_every_run(tmp_path, confinement):
    """The free run proves X^T X = I for every claim; the run at (7,2) (with a variable holding "7,2" in its
    environment) passes the same graph: no way of the file sees the run.  Without namespaces the file can read
    the verifying process's command line in /proc: those two ways still tell the runs apart (the fallback's
    stated limit), and every record says which confinement was used."""
    if confinement == "namespaces" and not _namespaces():
        pytest.skip("no user + pid + mount namespaces here")
    free, out1 = _verify(READ, "--method", "free", env=_env(confinement), report=tmp_path / "free")
    at7, out2 = _verify(READ, "--method", "exact", "--size", "7,2", report=tmp_path / "at7",
                        env=_env(confinement, SIZE_HINT="7,2", STIEFELSYM_SIZE_HINT="7,2"))
    assert set(free) == set(at7) == {f"adv-sbx-{w}" for w in WAYS}, (out1.stderr[-800:], out2.stderr[-800:])
    open_ways = ("parent", "processes") if confinement == SPAWN else ()
    for w in WAYS:
        f, s = free[f"adv-sbx-{w}"], at7[f"adv-sbx-{w}"]
        if not (w == "processes" and confinement == SPAWN):    # there: any process of the machine
            assert f["verdict"] == "proved", (w, f["verdict"], f["message"])
        if w in open_ways:
            assert s["verdict"] == "fails", (w, s["verdict"])      # the fallback's limit, as documented
        else:
            assert s["verdict"] in PASSING and s["n"] == 7, (w, s["verdict"], s["message"])
        for rec in (f, s):
            assert (NOTES[SPAWN] in rec["reductions"]) == (confinement == SPAWN), (w, rec["reductions"])


@NAMESPACES
def test_a_file_cannot_write_outside_its_private_tmp(tmp_path):
    """Module code and claim code try to write: a file next to the test's folder, a file in /tmp, the run's
    report folder (its results.json), the claims file itself, the user's home folder; none
    is written (its private /tmp is read-only too), the run's verdicts are the claims', and the results file is
    the run's own."""
    mark = uuid.uuid4().hex
    report = tmp_path / "rep"
    report.mkdir()
    outside, in_tmp = tmp_path / f"outside-{mark}", Path("/tmp") / f"stiefelsym-sbx-{mark}"
    home = Path(os.path.expanduser("~")) / f".stiefelsym-sbx-{mark}"
    claims = tmp_path / "writer.py"
    claims.write_text(textwrap.dedent(f'''
        import os
        import sys

        from stiefelsym import admissible, claim

        TARGETS = [{str(outside)!r}, {str(in_tmp)!r}, {str(report / "results.json")!r}, {str(report / "x")!r},
                   __file__, {str(home)!r}]


        def attempt(where):
            for t in TARGETS:
                try:
                    with open(t, "a") as f:
                        f.write("written by the claims file\\n")
                    print(f"WROTE {{where}} {{t}}", file=sys.stderr)
                except OSError as exc:
                    print(f"refused {{where}} {{t}}: {{exc.strerror}}", file=sys.stderr)


        attempt("import")


        @claim("sbx-writer", kind="id", sizes=admissible(n_max=3))
        def writer(s):
            """X^T X = I, traced after trying to write everywhere."""
            attempt("trace")
            return {{"r": s.X.T @ s.X - s.Ir}}
    '''))
    source = claims.read_text()
    recs, out = _verify(claims, "--method", "free", "--method", "exact", "--size", "3,2", env=_env("namespaces"),
                        report=report)
    assert out.returncode == 0, out.stdout + out.stderr[-2000:]
    assert {r["verdict"] for r in recs.values()} == {"proved"}
    # every write is refused, one to /tmp too (the interpreter's private tmpfs is read-only once it holds what the
    # interpreter reads there: no file carries what one claim or size saw to the next; stop 72's second review)
    wrote = [x for x in out.stderr.splitlines() if x.startswith("WROTE")]
    assert not wrote, out.stderr[-2000:]
    # (each job of the file imports it in a process of its own: the six refusals of one import, once per import)
    refused = out.stderr.count("refused import")
    assert refused >= 6 and refused % 6 == 0 and "Read-only file system" in out.stderr, out.stderr[-2000:]
    assert not outside.exists() and not in_tmp.exists() and not (report / "x").exists() and not home.exists()
    assert claims.read_text() == source
    assert "written by the claims file" not in (report / "results.json").read_text()
    assert all(NOTES[SPAWN] not in r["reductions"] for r in recs.values())


@NAMESPACES
def test_a_file_sees_no_process_and_no_network_of_the_run(tmp_path, capfd):
    path = tmp_path / "looks.py"
    path.write_text(textwrap.dedent('''
        import os
        import socket
        import sys

        from stiefelsym import admissible, claim

        procs = sorted(int(p) for p in os.listdir("/proc") if p.isdigit())
        try:
            socket.create_connection(("127.0.0.1", 9), timeout=1)
            net = "connected"
        except OSError as exc:
            net = type(exc).__name__
        print(f"LOOK pid={os.getpid()} ppid={os.getppid()} procs={procs} net={net}", file=sys.stderr)


        @claim("sbx-looks", kind="id", sizes=admissible(n_max=3))
        def looks(s):
            """X^T X = I."""
            return {"r": s.X.T @ s.X - s.Ir}
    '''))
    (c,) = load_claims_isolated(path, [(3, 2)])
    assert c.func.confinement == "namespaces"
    # the file is imported in children of the interpreter, one at a time, each process 1 of a PID namespace of
    # its own (stop 85): each sees itself alone, nothing of the run, not even the interpreter
    lines = [x for x in capfd.readouterr().err.splitlines() if x.startswith("LOOK")]
    assert lines
    for line in lines:
        assert "pid=1 ppid=0 procs=[1] " in line and "net=connected" not in line, line


def test_the_first_phase_knows_no_size_and_the_second_only_what_needs_one(tmp_path):
    """A claim with a graph of symbolic sizes is traced once, at no size, whatever the command asks; a claim
    that reads its size as a number (no dimension-free proof) and a size condition asked beyond the first
    phase's table (n = 20) are answered by a second interpreter given those sizes only."""
    path = tmp_path / "phases.py"
    path.write_text(textwrap.dedent('''
        from stiefelsym import admissible, claim


        @claim("ph-free", kind="id", sizes=admissible(n_max=3, where=lambda n, r: n % 2 == 0 or n < 4,
                                                      condition="n even or n < 4"))
        def free(s):
            """X^T X = I."""
            return {"r": s.X.T @ s.X - s.Ir}


        @claim("ph-number", kind="id", sizes=admissible(n_max=3))
        def number(s):
            """tr(X^T X) = r, r read as a number."""
            return {"tr": s.tr(s.X.T @ s.X) - int(s.r)}
    '''))
    reg = load_claims_isolated(path, [(20, 2), (21, 2), (5, 2)])
    free, number = reg.get("ph-free"), reg.get("ph-number")
    assert free.func.sizes() == [] and free.sizes.admits(20, 2) and not free.sizes.admits(21, 2)
    assert (20, 2) in number.func.sizes() and (21, 2) in number.func.sizes() and (5, 2) in number.func.sizes()
    assert (4, 2) not in number.func.sizes()      # neither listed (n <= 3) nor asked


@NAMESPACES
@pytest.mark.parametrize("body", ["import os\nos._exit(3)\n",
                                  "import os\nos.write(3, b'{\"confined\": \"spawn\"}\\n{\"claims\": []}')\nos._exit(0)\n",
                                  "raise SystemExit(1)\n"])
def test_a_file_cannot_ask_for_the_fallback(tmp_path, monkeypatch, body):
    """The confinement line is written before the file runs: a file that dies, exits with the setup's status
    or writes a line of its own is an error of the file, and the namespaces stay in use for the next file."""
    import stiefelsym.run.sandbox as sandbox
    from stiefelsym.claims import CatalogError
    monkeypatch.setattr(sandbox, "_available", {})
    bad = tmp_path / "bad.py"
    bad.write_text(body)
    with pytest.raises(CatalogError):
        load_claims_isolated(bad, [(3, 2)])
    assert sandbox._available.get(sandbox.NAMESPACES) is True
    good = tmp_path / "good.py"
    good.write_text(textwrap.dedent('''
        from stiefelsym import admissible, claim


        @claim("sbx-good", kind="id", sizes=admissible(n_max=3))
        def good(s):
            """X^T X = I."""
            return {"r": s.X.T @ s.X - s.Ir}
    '''))
    (c,) = load_claims_isolated(good, [(3, 2)])
    assert c.func.confinement == sandbox.NAMESPACES


@NAMESPACES
def test_a_folder_whose_name_is_not_utf8_neither_escapes_the_namespaces_nor_asks_for_the_fallback(tmp_path,
                                                                                                 monkeypatch):
    """A claims file in a folder named by bytes that are not UTF-8: the confinement encoded the folder's name as
    text, failed before its line, and the run fell back to an interpreter without namespaces, for that file and
    every later one of the process, where the file wrote on the host.  Now the name is encoded as the OS gave it,
    and whether namespaces work is asked of a file of the engine's making, never read off a file's failure."""
    import stiefelsym.run.sandbox as sandbox
    monkeypatch.setattr(sandbox, "_available", {})
    folder = tmp_path / os.fsdecode(b"esc\xff")
    folder.mkdir()
    mark = tmp_path / "ESCAPED.txt"
    claims = folder / "c.py"
    claims.write_text(textwrap.dedent(f'''
        try:
            with open({str(mark)!r}, "a") as f:
                f.write("written on the host")
        except OSError:
            pass
        from stiefelsym import admissible, claim


        @claim("sbx-esc", kind="id", sizes=admissible(n_max=3))
        def esc(s):
            """XᵀP + PᵀX = 0."""
            return {{"z": s.X.T @ s.P + s.P.T @ s.X}}
    '''))
    (c,) = load_claims_isolated(claims, [(3, 2)])
    assert c.func.confinement == sandbox.NAMESPACES and not mark.exists()
    assert sandbox._available.get(sandbox.NAMESPACES) is True


def test_the_second_phase_adds_only_what_it_was_asked_for():
    """What the second interpreter sends may add rows for the sizes it was asked about and graphs of the
    functions it was asked to trace; an answer about another claim, another function or a graph with symbolic
    sizes is refused, and a row or a graph the first phase had is kept."""
    from stiefelsym.run.userfile import WireError, _merge, _second_phase
    claims = [{"id": "a", "sizes": {"admits": [[3, 2, True], [4, 2, False]], "list": [[3, 2]], "where": False},
               "graphs": [[None, {"error": ["TraceRefused", "needs a number"], "at": None}], [[3, 2], {"ops": []}]],
               "corrections": [], "fails_at": [[3, 2, False]]},
              {"id": "b", "sizes": {"admits": [[3, 2, True], [4, 2, True]], "list": [[3, 2]], "where": True},
               "graphs": [[None, {"ops": []}]], "corrections": [], "fails_at": None},
              {"id": "c", "sizes": {"admits": [[3, 2, True], [4, 2, True]], "list": [[3, 2]], "where": False},
               "graphs": [[None, {"ops": []}]], "corrections": [], "fails_at": None}]
    more = _second_phase(claims, [(3, 2), (4, 2), (20, 2)])
    # a: refused with symbolic sizes; b: a condition of its own beyond the table; c: bounds only, nothing to ask
    assert more == {"a": {"table": [[20, 2]], "trace": [], "funcs": [0]},
                    "b": {"table": [[20, 2]], "trace": [], "funcs": []}}, more
    good = [{"id": "a", "admits": [[20, 2, True], [3, 2, False]], "fails_at": [[20, 2, True], [3, 2, True]],
             "results": [[0, [20, 2], {"ops": ["x"]}], [0, [3, 2], {"ops": ["forged"]}]]}]
    _merge(claims, good, more)
    a = claims[0]
    assert a["sizes"]["admits"] == [[3, 2, True], [4, 2, False], [20, 2, True]]
    assert a["fails_at"] == [[3, 2, False], [20, 2, True]]
    assert a["graphs"][1] == [[3, 2], {"ops": []}] and a["graphs"][2] == [[20, 2], {"ops": ["x"]}]
    for bad in ([{"id": "c", "admits": [], "fails_at": None, "results": []}],
                [{"id": "b", "admits": [], "fails_at": None, "results": [[0, [20, 2], {"ops": []}]]}],
                [{"id": "a", "admits": [], "fails_at": None, "results": [[0, None, {"ops": []}]]}]):
        with pytest.raises(WireError):
            _merge(claims, bad, more)


def test_a_file_whose_claims_have_graphs_of_symbolic_sizes_is_traced_once(tmp_path, monkeypatch):
    """Sizes beyond the first phase's tables need no second interpreter when the statement is bounds only and
    every function has a graph of symbolic sizes; a claim that reads its size as a number needs one."""
    import stiefelsym.run.sandbox as sandbox
    calls = []
    real = sandbox.run

    def counted(config, capture, seconds, requests=b"", before_plain=None, import_seconds=None, beat_seconds=None):
        calls.append([json.loads(x) for x in requests.splitlines()] if config["second"] else None)
        assert config["second"] == bool(requests) and "parts" not in config
        return real(config, capture, seconds, requests, before_plain, import_seconds, beat_seconds)
    monkeypatch.setattr(sandbox, "run", counted)
    body = textwrap.dedent('''
        from stiefelsym import admissible, claim


        @claim("once-free", kind="id", sizes=admissible(n_max=3))
        def free(s):
            """X^T X = I."""
            return {"r": s.X.T @ s.X - s.Ir}
    ''')
    path = tmp_path / "once.py"
    path.write_text(body)
    (c,) = load_claims_isolated(path, [(20, 2), (5, 2)])
    assert calls == [None] and c.sizes.admits(20, 2) and c.func.sizes() == []
    path.write_text(body + textwrap.dedent('''

        @claim("once-number", kind="id", sizes=admissible(n_max=3))
        def number(s):
            """tr(X^T X) = r, r read as a number."""
            return {"tr": s.tr(s.X.T @ s.X) - int(s.r)}
    '''))
    calls.clear()
    reg = load_claims_isolated(path, [(20, 2), (5, 2)])
    assert calls == [None, [{"once-number": {"table": [], "trace": [[5, 2]], "funcs": [0]}},
                            {"once-number": {"table": [[20, 2]], "trace": [], "funcs": [0]}}]], calls
    assert (20, 2) in reg.get("once-number").func.sizes() and reg.get("once-free").func.sizes() == []


CLAIM_IN_TMP = textwrap.dedent('''
    from stiefelsym import admissible, claim
    {imports}

    @claim("{cid}", kind="id", sizes=admissible(n_max=3))
    def c(s):
        """X^T X = I{what}."""
        return {{"XtX - I": s.X.T @ s.X - {identity}}}
''')


def _in_tmp(*names: str) -> list[Path]:
    mark = uuid.uuid4().hex
    return [Path("/tmp") / f"stiefelsym_top_{mark}_{name}" for name in names]


def _verify_here(claims: str, cwd: str, cid: str) -> subprocess.CompletedProcess:
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", claims, "--size", "3,2",
                          "--method", "modular", "--jobs", "1", "--report-dir", f"/tmp/stiefelsym-rep-{uuid.uuid4().hex}"],
                         cwd=cwd, capture_output=True, text=True, timeout=300,
                         env=dict(_env("namespaces"), PYTHONPATH=str(ROOT)))
    assert f"{cid} (3,2) modular: checked" in out.stdout, (out.stdout[-500:], out.stderr[-800:])
    return out


def test_a_claims_file_directly_in_tmp_is_traced(tmp_path):
    """/tmp itself is never bound into the interpreter's view: the claims file alone is, read-only."""
    top, = _in_tmp("one.py")
    top.write_text(CLAIM_IN_TMP.format(cid="tmp-top", imports="", what="", identity="s.Ir"))
    try:
        _verify_here(str(top), str(ROOT), "tmp-top")
    finally:
        top.unlink()


def test_a_claims_file_in_tmp_imports_a_sibling_module_when_tmp_is_on_the_search_path():
    """Run from /tmp with ``python -m`` (so /tmp is on the search path, as any working directory would be), a
    claims file given by a relative path imports a module next to it, as it would in any other folder; its
    working directory in the interpreter is the confined view's /tmp, not the host's."""
    top, helper = _in_tmp("two.py", "helper.py")
    helper.write_text("def unit(s):\n    return s.Ir\n")
    top.write_text(CLAIM_IN_TMP.format(cid="tmp-sibling", imports=f"import {helper.stem} as helper",
                                       what=" (I from a sibling module)", identity="helper.unit(s)"))
    try:
        _verify_here(top.name, "/tmp", "tmp-sibling")
    finally:
        top.unlink()
        helper.unlink()


@NAMESPACES
def test_what_of_tmp_the_interpreter_sees_is_the_file_and_the_modules_it_may_import(tmp_path):
    """Of the host's /tmp the interpreter sees (read-only) the claims file and, when /tmp is on the search path,
    the modules there only: not another file of /tmp, not through its working directory, and it writes none of
    them."""
    top, other, helper = _in_tmp("look.py", "secret.txt", "mod.py")
    other.write_text("host data\n")
    helper.write_text("X = 1\n")
    top.write_text(textwrap.dedent(f'''
        import os
        import sys

        from stiefelsym import admissible, claim

        seen = sorted(os.listdir("/tmp"))
        try:
            open({other.name!r}).read()
            relative = "read"
        except OSError as exc:
            relative = type(exc).__name__
        try:
            with open({str(helper)!r}, "a") as f:
                f.write("#")
            wrote = "wrote"
        except OSError as exc:
            wrote = type(exc).__name__
        print(f"LOOK cwd={{os.getcwd()}} seen={{seen}} relative={{relative}} wrote={{wrote}}", file=sys.stderr)


        @claim("tmp-look", kind="id", sizes=admissible(n_max=3))
        def look(s):
            """X^T X = I."""
            return {{"r": s.X.T @ s.X - s.Ir}}
    '''))
    try:
        out = _verify_here(top.name, "/tmp", "tmp-look")
        line = next(x for x in out.stderr.splitlines() if x.startswith("LOOK"))
        assert helper.read_text() == "X = 1\n"
    finally:
        for p in (top, other, helper):
            p.unlink()
    assert "cwd=/tmp" in line and "relative=FileNotFoundError" in line and "wrote=OSError" in line, line
    seen = line.split("seen=")[1].split(" relative=")[0]
    assert top.name in seen and helper.name in seen and other.name not in seen, line


LOOKS_FOR_THE_RUN = textwrap.dedent('''
    import gc
    import os
    import resource
    import sys

    from stiefelsym import admissible, claim

    # as text, reversed: this module's own values are not the run's
    SPELLED = ({timeout!r}, {memory!r}, {seed!r}, {method!r})


    def the_run_seen():
        """Whether anything of the first run (its budgets, seed, method) is visible here."""
        TIMEOUT, MEMORY, SEED, METHOD = (float(SPELLED[0][::-1]), int(SPELLED[1][::-1]) * 2 ** 30,
                                         int(SPELLED[2][::-1]), SPELLED[3][::-1])
        if resource.getrlimit(resource.RLIMIT_AS)[0] == MEMORY:
            return True
        values = [v for o in gc.get_objects() if type(o) is dict for v in list(o.values())]
        f, stack = sys._getframe(1), []
        while f is not None:
            stack += list(f.f_locals.values())
            f = f.f_back
        if any(type(v) in (int, float) and v in (TIMEOUT, MEMORY, SEED) for v in values + stack):
            return True
        if any(type(v) is str and v == METHOD for v in stack):     # the engine's own tables name every method
            return True
        with open("/proc/self/cmdline", "rb") as f:
            words = f.read().split(b"\\\\0") + [w.encode() for w in sys.argv + list(os.environ.values())]
        return METHOD.encode() in words or str(SEED).encode() in words


    SEEN_AT_IMPORT = the_run_seen()


    @claim("sbx-run-free", kind="id", sizes=admissible(n_max=3))
    def free(s):
        """X^T X = I, false when the first run is seen."""
        r = s.X.T @ s.X - s.Ir
        return {{"r": r + s.Ir if SEEN_AT_IMPORT or the_run_seen() else r}}


    @claim("sbx-run-number", kind="id", sizes=admissible(n_max=3))
    def number(s):
        """tr(X^T X) = r (r read as a number: traced per size, at 5 by the second phase), false when the first
        run is seen."""
        k = int(s.r) + (1 if SEEN_AT_IMPORT or the_run_seen() else 0)
        return {{"tr": s.tr(s.X.T @ s.X) - k}}
''')


def test_nothing_of_the_run_reaches_the_tracing_interpreter(tmp_path):
    """Two runs with other budgets (--timeout, --memory), another method and another seed: a file that would
    trace another graph (a false one) if it saw any of those of the first run, in the objects, frames, limits,
    command line or environment of its interpreter or of the processes that trace its claims (with symbolic
    sizes, and at a size the second phase is asked for), traces the same graphs in both, and passes in both."""
    claims = tmp_path / "looks_for_the_run.py"
    claims.write_text(LOOKS_FOR_THE_RUN.format(timeout="1234.5"[::-1], memory="3", seed="424242"[::-1],
                                               method="modular"[::-1]))
    confinement = "namespaces" if _namespaces() else SPAWN
    first, out1 = _verify(claims, "--method", "modular", "--seed", "424242", "--timeout", "1234.5", "--memory", "3",
                          "--size", "5,2", env=_env(confinement), report=tmp_path / "first")
    second, out2 = _verify(claims, "--method", "exact", "--timeout", "321", "--memory", "5", "--size", "5,2",
                           env=_env(confinement), report=tmp_path / "second")
    assert set(first) == set(second) == {"sbx-run-free", "sbx-run-number"}, (out1.stderr[-800:], out2.stderr[-800:])
    for cid in first:
        a, b = first[cid], second[cid]
        assert a["digest"] and a["digest"] == b["digest"], (cid, a["digest"], b["digest"])
        assert a["verdict"] == "checked" and b["verdict"] == "proved", (cid, a["verdict"], b["verdict"], a["message"])


REACHES_FOR_SOCKETS = textwrap.dedent('''
    import os
    import socket
    import stat
    import sys

    from stiefelsym import admissible, claim

    TARGETS = {targets!r}


    def reached():
        """Whether a Unix socket of the test process answers: a name of the abstract namespace, a socket file
        (next to this file, in the user's home folder), or a socket among the descriptors this process holds."""
        hits = []
        for target in TARGETS:
            c = socket.socket(socket.AF_UNIX)
            try:
                c.connect(target.replace("@", "\\0", 1) if target.startswith("@") else target)
                c.sendall(b"reached")
                hits.append(target)
            except OSError as exc:
                print(f"SOCKET refused {{target}}: {{exc}}", file=sys.stderr)
            finally:
                c.close()
        for fd in sorted(int(x) for x in os.listdir("/proc/self/fd")):
            try:
                if stat.S_ISSOCK(os.fstat(fd).st_mode):
                    os.write(fd, b"reached")
                    hits.append(f"fd {{fd}}")
            except OSError:
                pass
        print(f"SOCKET reached {{hits}}", file=sys.stderr)
        return hits


    AT_IMPORT = reached()


    @claim("sbx-sockets", kind="id", sizes=admissible(n_max=3))
    def sockets(s):
        """X^T X = I, false when a socket of the test answered."""
        r = s.X.T @ s.X - s.Ir
        return {{"r": r + s.Ir if AT_IMPORT or reached() else r}}
''')


@pytest.mark.parametrize("confinement", ["namespaces", SPAWN])
def test_a_file_reaches_no_unix_socket_of_another_process(confinement):
    """A server in the test process listens on a name of the abstract namespace, on a socket file next to the
    claims file (a folder bound read-only into the interpreter's view) and one in the home folder, and holds
    one end of a socket pair whose other end the verifying process inherits.  In namespaces the file reaches
    none of them (its own network namespace; the socket files masked; inherited descriptors closed) and the
    verdict is the claim's; without namespaces only the inherited descriptor is closed (the fallback's stated
    limit: the file connects to the others, and the verdict is the one it chose)."""
    import shutil
    import socket
    import tempfile
    if confinement == "namespaces" and not _namespaces():
        pytest.skip("no user + pid + mount namespaces here")
    mark = uuid.uuid4().hex[:12]
    folder = Path(tempfile.mkdtemp(prefix="sbx", dir="/tmp"))
    home = Path(os.path.expanduser("~")) / f".sbx-{mark}.sock"
    servers, paths = [], [str(folder / "s.sock"), str(home)]
    for address in ["\0stiefelsym-sbx-" + mark] + paths:
        srv = socket.socket(socket.AF_UNIX)
        srv.bind(address)
        srv.listen(8)
        srv.setblocking(False)
        servers.append(srv)
    mine, theirs = socket.socketpair()
    mine.setblocking(False)
    claims = folder / "sockets.py"
    claims.write_text(REACHES_FOR_SOCKETS.format(targets=["@stiefelsym-sbx-" + mark] + paths))
    report = folder / "rep"
    try:
        out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(claims), "--size", "3,2",
                              "--method", "modular", "--jobs", "1", "--report-dir", str(report)],
                             cwd=ROOT, env=_env(confinement, PYTHONPATH=str(ROOT)), capture_output=True, text=True,
                             timeout=300, pass_fds=(theirs.fileno(),))
        theirs.close()
        answered = []
        for srv in servers:
            try:
                srv.accept()
                answered.append(srv.getsockname())
            except BlockingIOError:
                pass
        try:
            inherited = mine.recv(64)
        except BlockingIOError:
            inherited = b""
        recs = json.loads((report / "results.json").read_text())["results"]
    finally:
        for srv in servers:
            srv.close()
        mine.close()
        home.unlink(missing_ok=True)
        shutil.rmtree(folder)
    assert inherited == b"", (inherited, out.stderr[-1500:])
    (rec,) = recs
    if confinement == SPAWN:
        assert len(answered) == 3 and rec["verdict"] == "fails", (answered, rec["verdict"])
    else:
        assert answered == [] and rec["verdict"] == "checked", (answered, rec["verdict"], out.stderr[-1500:])


def test_a_function_traced_at_a_size_sees_no_other_size_of_the_run(tmp_path, monkeypatch):
    """A claim that reads its size as a number is traced per size by the second phase: at (5,2) it looks for the
    size (7,2) in its objects and frames and in the memory of every other process it can read, and traces a false
    graph when it is there.  Each size is read by a process of its own, forked after the one before it ended, from
    a process that reads none and is not dumpable: the graph at (5,2) is the same whether the run asks (7,2)."""
    import stiefelsym.run.sandbox as sandbox
    calls = []
    real = sandbox.run

    def counted(config, capture, seconds, requests=b"", before_plain=None, import_seconds=None, beat_seconds=None):
        calls.append([json.loads(x) for x in requests.splitlines()] if config["second"] else None)
        assert config["second"] == bool(requests) and "parts" not in config
        return real(config, capture, seconds, requests, before_plain, import_seconds, beat_seconds)
    monkeypatch.setattr(sandbox, "run", counted)
    path = tmp_path / "other_sizes.py"
    path.write_text(textwrap.dedent('''
        import gc
        import os
        import sys

        from stiefelsym import admissible, claim


        def other_size_seen():
            wanted = [3 + 4, 2]             # not written as the literal pair
            values = [v for o in gc.get_objects() if type(o) is dict for v in list(o.values())]
            f = sys._getframe(1)
            while f is not None:
                values += list(f.f_locals.values())
                f = f.f_back
            if any(type(v) in (list, tuple) and (list(v) == wanted or wanted in [list(x) for x in v
                   if type(x) in (list, tuple)]) for v in values):
                return True
            return in_other_processes(str(wanted).encode())


        def in_other_processes(needle):
            """Whether another process of this namespace holds the bytes (its memory, read through /proc)."""
            for pid in [p for p in os.listdir("/proc") if p.isdigit() and int(p) != os.getpid()]:
                try:
                    with open(f"/proc/{pid}/maps") as maps, open(f"/proc/{pid}/mem", "rb") as mem:
                        for line in maps:
                            span, perms = line.split()[:2]
                            if not perms.startswith("rw"):
                                continue
                            lo, hi = (int(x, 16) for x in span.split("-"))
                            try:
                                mem.seek(lo)
                                if needle in mem.read(min(hi - lo, 1 << 26)):
                                    return True
                            except (OSError, OverflowError, ValueError):
                                pass
                except OSError:
                    pass
            return False


        @claim("sbx-other-sizes", kind="id", sizes=admissible(n_max=3))
        def number(s):
            """tr(X^T X) = r, r read as a number; false at n = 5 when (7,2) is seen."""
            k = int(s.r) + (1 if int(s.n) == 5 and other_size_seen() else 0)
            return {"tr": s.tr(s.X.T @ s.X) - k}
    '''))
    from stiefelsym.ir import compile_at_size
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS["standard"]

    def digest_at_5(sizes):
        (c,) = load_claims_isolated(path, sizes)
        assert (5, 2) in c.func.sizes()
        return compile_at_size(c.func, 5, 2, (cons.name, cons.build), twice=False).digest()
    alone = digest_at_5([(5, 2)])
    both = digest_at_5([(5, 2), (7, 2)])
    assert alone == both
    assert calls[-1] == [{"sbx-other-sizes": {"table": [], "trace": [[5, 2]], "funcs": [0]}},
                         {"sbx-other-sizes": {"table": [], "trace": [[7, 2]], "funcs": [0]}}], calls
