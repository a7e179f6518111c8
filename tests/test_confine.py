"""What a claims file's child leaves behind: processes (ended when the child ends) and edits to the engine's
files (the run stops)."""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from stiefelsym.claims import CatalogError
from stiefelsym.run.confine import Confined, changed_files, engine_files, package_roots, path_modules
from stiefelsym.run.userfile import load_claims_isolated

LINUX = pytest.mark.skipif(not sys.platform.startswith("linux") or not os.path.isdir("/proc/self"),
                           reason="the subreaper and /proc are Linux's")

CLAIM = '''
from stiefelsym import admissible, claim


@claim("confine-true", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"),
       statement="X^T X = I_r")
def true(s):
    """True."""
    return {"r": s.X.T @ s.X - s.Ir}
'''


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rpartition(")")[2].split()[0] not in ("Z", "X")
    except OSError:
        return False


def _with_marker(marker: str) -> list[int]:
    """The processes whose command line holds ``marker``."""
    out = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/cmdline", "rb") as f:
                    if marker.encode() in f.read() and _alive(int(entry)):
                        out.append(int(entry))
            except OSError:
                pass
    return out


@pytest.fixture(params=["spawn", "namespaces"])
def confinement(request, monkeypatch):
    """Each test once with the plain spawn (the subreaper and the digest are what confine the file) and once in
    namespaces (skipped where they are not available)."""
    import stiefelsym.run.sandbox as sandbox
    monkeypatch.setattr(sandbox, "_available", {})
    if request.param == "spawn":
        monkeypatch.setenv(sandbox.CONFINE_ENV, "spawn")
    elif not namespaces_available():
        pytest.skip("no user + pid + mount namespaces here (unshare)")
    return request.param


def namespaces_available() -> bool:
    from stiefelsym.run.sandbox import namespaces_available as available
    return available()


def _daemon_file(tmp_path: Path, close_fds: bool) -> tuple[Path, str]:
    """A claims file whose child leaves a process in a session of its own (double fork, setsid) that sleeps a
    minute (a program whose command line holds a marker), holding (or not) every descriptor it inherited, the
    pipe to the verifying process included."""
    marker = f"60.{os.getpid()}{int(time.time() * 1000) % 10 ** 6:06d}{int(close_fds)}"
    closing = "os.closerange(3, 4096)" if close_fds else "pass"
    src = textwrap.dedent(f'''
        import os
        import sys
        import time
        if os.fork() == 0:
            os.setsid()
            if os.fork() == 0:
                try:
                    print("daemon-started", file=sys.stderr, flush=True)
                    {closing}
                    os.execv("/bin/sleep", ["sleep", {marker!r}])
                finally:
                    os._exit(0)
            os._exit(0)
        time.sleep(0.3)         # the grandchild runs
    ''') + CLAIM
    path = tmp_path / "daemon_claims.py"
    path.write_text(src)
    return path, marker


@LINUX
@pytest.mark.parametrize("close_fds", [False, True])
def test_a_process_the_file_leaves_is_ended_with_its_child_and_does_not_hold_the_run(tmp_path, close_fds,
                                                                                      confinement, capfd):
    path, marker = _daemon_file(tmp_path, close_fds)
    t = time.monotonic()
    reg = load_claims_isolated(path, [(3, 2)])
    took = time.monotonic() - t
    assert list(reg.ids()) == ["confine-true"]
    assert took < 30, took                      # the process holding the pipe sleeps 60 s
    assert "daemon-started" in capfd.readouterr().err
    assert _with_marker(marker) == [], "the process the file left is still running"


@LINUX
def test_children_the_process_had_before_are_left_alone(tmp_path, confinement):
    mine = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        path, _ = _daemon_file(tmp_path, True)
        load_claims_isolated(path, [(3, 2)])
        assert mine.poll() is None and _alive(mine.pid)
    finally:
        mine.kill()
        mine.wait()


@LINUX
def test_confined_kills_a_whole_subtree_but_not_the_older_children():
    older = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        with Confined() as c:
            assert c.active
            pid = os.fork()
            if pid == 0:                        # a child that leaves a grandchild in a session of its own
                if os.fork() == 0:
                    os.setsid()
                    time.sleep(60)
                    os._exit(0)
                os._exit(0)
            os.waitpid(pid, 0)
            deadline = time.monotonic() + 10
            while not c.descendants() and time.monotonic() < deadline:
                time.sleep(0.01)
            left = c.descendants()
            assert left and older.pid not in left
        assert all(not _alive(p) for p in left), left
        assert older.poll() is None
    finally:
        older.kill()
        older.wait()


def test_engine_files_see_a_change_an_addition_and_a_removal(tmp_path):
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "a.py").write_text("x = 1\n")
    (pkg / "sub" / "b.py").write_text("y = 2\n")
    before = engine_files([pkg])
    assert changed_files(before, engine_files([pkg])) == []
    (pkg / "a.py").write_text("x = 1\nx = 2\n")
    (pkg / "sub" / "c.py").write_text("")
    (pkg / "sub" / "b.py").unlink()
    changed = changed_files(before, engine_files([pkg]))
    assert changed == sorted(str(pkg / p) for p in ("a.py", "sub/b.py", "sub/c.py"))


def test_the_package_roots_hold_the_engine_and_the_catalog():
    import stiefelsym
    roots = package_roots()
    assert Path(os.path.realpath(stiefelsym.__path__[0])) in roots
    files = engine_files(roots)
    assert any(p.endswith(os.sep + "report.py") for p in files)


def test_a_claims_file_whose_child_edits_the_engine_is_refused(tmp_path, monkeypatch, confinement):
    """The digest check on its own (the module's roots pointed at a scratch directory the file edits); in
    namespaces the edit itself fails (the file system is read-only there) and the file is refused for it."""
    import stiefelsym.run.confine as confine
    scratch = tmp_path / "engine"
    scratch.mkdir()
    (scratch / "mod.py").write_text("x = 1\n")
    monkeypatch.setattr(confine, "package_roots", lambda: [scratch])
    path = tmp_path / "edits.py"
    path.write_text(f"open({str(scratch / 'mod.py')!r}, 'a').write('x = 2\\n')\n" + CLAIM)
    refusal = "changed on disk.*mod.py" if confinement == "spawn" else "Read-only file system"
    with pytest.raises(CatalogError, match=refusal):
        load_claims_isolated(path, [(3, 2)])
    text = (scratch / "mod.py").read_text()
    if confinement == "namespaces":
        assert text == "x = 1\n"
    else:       # (once per import of the file: each of its jobs imports it)
        assert text.startswith("x = 1\nx = 2\n") and set(text.splitlines()[1:]) == {"x = 2"}, text
    honest = tmp_path / "honest.py"
    honest.write_text(CLAIM)
    (c,) = load_claims_isolated(honest, [(3, 2)])
    assert c.id == "confine-true" and c.func.confinement == confinement


def test_the_verifying_process_imports_the_whole_package_before_the_fork():
    code = ("import sys; from stiefelsym.run.userfile import _preload; _preload(); "
            "print(all(m in sys.modules for m in ('stiefelsym.reports.report', 'stiefelsym.cli.check', "
            "'stiefelsym.reports.flows_report', 'stiefelsym.analyses.speed', 'stiefelsym.analyses.mutate')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                         env=dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[1])))
    assert out.stdout.strip() == "True", out.stderr[-800:]


@pytest.mark.parametrize("mode", ["spawn", "namespaces"])
def test_the_whole_package_is_imported_before_an_interpreter_without_namespaces(tmp_path, mode):
    """Without namespaces the file writes with the user's rights: the verifying process has imported the whole
    package before that interpreter is spawned.  In namespaces it writes nowhere on the host (the edit of the test
    above fails there), so the package is not imported first; the digests are taken before it either way."""
    if mode == "namespaces" and not namespaces_available():
        pytest.skip("no user + pid + mount namespaces here (unshare)")
    path = tmp_path / "honest.py"
    path.write_text(CLAIM)
    code = textwrap.dedent(f'''
        import sys
        import stiefelsym.run.sandbox as sandbox
        import stiefelsym.run.userfile as userfile
        seen, digests, real_spawn, real_digests = [], [], sandbox._spawn, userfile._digests
        def spawn(config, capture, seconds, unshare, requests=b"", import_seconds=None, beat_seconds=None):
            seen.append((unshare is not None, "stiefelsym.analyses.speed" in sys.modules, len(digests)))
            return real_spawn(config, capture, seconds, unshare, requests, import_seconds, beat_seconds)
        def counted():
            digests.append(1)
            return real_digests()
        sandbox._spawn, userfile._digests = spawn, counted
        (c,) = userfile.load_claims_isolated({str(path)!r}, [(3, 2)])
        print(c.func.confinement, seen)
    ''')
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[1]))
    env.pop("STIEFELSYM_CONFINE", None)
    if mode == "spawn":
        env["STIEFELSYM_CONFINE"] = "spawn"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, env=env)
    # (namespaces: one interpreter, the package not imported, the digests taken once before it; spawn: the
    # package imported and the digests taken again after the import, which may write byte code)
    expected = "namespaces [(True, False, 1)]" if mode == "namespaces" else "spawn [(False, True, 2)]"
    assert out.stdout.strip() == expected, out.stderr[-800:]


def test_path_modules_sees_a_module_put_before_a_library(tmp_path):
    """A top-level module, byte code, extension, .pth file or package __init__ added to (or changed in) a directory
    of the import path is a change; a plain folder (a namespace portion, which never shadows a module found later
    on the path), a data file and a file deep inside a package are not."""
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "__init__.py").write_text("")
    (tmp_path / "pkg" / "deep.py").write_text("")
    before = path_modules([str(tmp_path)])
    assert str(tmp_path / "pkg" / "__init__.py") in before
    (tmp_path / "data.json").write_text("{}")
    (tmp_path / "folder").mkdir()
    (tmp_path / "pkg" / "deep.py").write_text("x = 1")
    assert changed_files(before, path_modules([str(tmp_path)])) == []
    for name in ("sympy.py", "numpy.pyc", "flint.cpython-311-x86_64-linux-gnu.so", "evil.pth"):
        (tmp_path / name).write_text("")
        assert changed_files(before, path_modules([str(tmp_path)])) == [str(tmp_path / name)]
        (tmp_path / name).unlink()
    (tmp_path / "pkg" / "__init__.py").write_text("import os")
    assert changed_files(before, path_modules([str(tmp_path)])) == [str(tmp_path / "pkg" / "__init__.py")]


def test_a_module_written_beside_the_claims_file_is_named_as_such(tmp_path, monkeypatch, confinement):
    """A module added to the claims file's own folder, on the import path (the working directory of
    ``python -m stiefelsym``), while it ran is named as that, not as a change of the engine's files (stop 91 h1 M1:
    a user wrote an unrelated file beside a long load)."""
    monkeypatch.syspath_prepend(str(tmp_path))
    path = tmp_path / "writes.py"
    path.write_text(f"open({str(tmp_path / 'sibling.py')!r}, 'w').write('y = 1\\n')\n" + CLAIM)
    refusal = ("a module in the claims file's own folder .*changed on disk.*sibling.py" if confinement == "spawn"
               else "Read-only file system|changed on disk")
    with pytest.raises(CatalogError, match=refusal):
        load_claims_isolated(path, [(3, 2)])
