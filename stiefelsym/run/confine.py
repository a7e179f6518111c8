"""What a user's claims file may leave behind once its interpreter has run: processes, and edits to the engine.

A claims file is imported in a spawned interpreter (:mod:`stiefelsym.run.userfile`, :mod:`stiefelsym.run.sandbox`).
In namespaces (where the platform has them) that interpreter writes nowhere (its private /tmp is read-only) and its
processes end with its pid namespace; without them it runs with the user's rights: it can start processes
that outlive it, and write files.  Two things keep that from reaching a verdict of the verifying process,
whichever confinement was used:

* :class:`Confined` makes the verifying process a *child subreaper* (Linux ``prctl(PR_SET_CHILD_SUBREAPER)``)
  while the file's interpreter runs, so that every process the file starts stays a descendant of this process
  whatever it does (a double fork, ``setsid``: an orphan is re-parented to the subreaper, not to init); when
  the interpreter has ended, :meth:`Confined.end_the_rest` kills every process of that subtree (found in
  ``/proc``) before anything of the run is written.  Where there is no subreaper or no ``/proc`` only the
  interpreter's process group is killed (the README's security notes say so).
* :func:`engine_files` is a digest of every file of the package (``stiefelsym`` and its ``proofs``),
  taken before the first interpreter is spawned and compared when it returns: an engine module rewritten on
  disk by the file stops the run (:class:`EngineFilesChanged`).  Before an interpreter without namespaces (where
  the file writes with the user's rights; in namespaces it writes nowhere on the host's file system) the verifying
  process has also imported every module it can need later (:func:`import_package`), so no engine module it runs
  afterwards is read from disk.  The libraries it imports lazily (sympy, platformdirs) are found on the
  import path when first used, possibly after the file ran: :func:`path_modules`, compared likewise, stamps
  every top-level module of the directories on ``sys.path`` (inode, size, modification and status-change
  times; the working directory under ``python -m``), so a module of a library's name put before the library
  itself stops the run too.
"""
from __future__ import annotations

import hashlib
import importlib
import os
import signal
import sys
import time
from pathlib import Path

#: prctl options (linux/prctl.h)
PR_SET_CHILD_SUBREAPER = 36
#: modules of the package the verifying process never imports: the entry point, and the plugins that other
#: tools (dask, pytest) load into their own processes
NOT_PRELOADED = ("stiefelsym.__main__", "stiefelsym.run._dask_plugin", "stiefelsym.pytest_plugin")
#: seconds to end the processes a claims file left behind
END_SECONDS = 10.0


class EngineFilesChanged(RuntimeError):
    """A file of the engine changed on disk while a user's claims file ran."""


class ProcessesLeft(RuntimeError):
    """Processes a user's claims file started could not be ended."""


# --------------------------------------------------------------------------- the engine on disk

def import_package() -> None:
    """Import every module of the package (but :data:`NOT_PRELOADED`) and what its modules import on first
    use, so that the verifying process reads no engine module from disk after a claims file's child ran."""
    import pkgutil

    for info in pkgutil.walk_packages(_package_path(), "stiefelsym.", onerror=lambda name: None):
        if info.name in NOT_PRELOADED or info.name in sys.modules:
            continue
        try:
            importlib.import_module(info.name)
        except Exception:   # noqa: BLE001 - an optional dependency missing: the module fails the same later
            pass
    for name, module in list(sys.modules.items()):
        if name.startswith("stiefelsym.") or name == "stiefelsym":
            for v in list(vars(module).values()):
                if type(v).__name__ == "_LazyModule" and type(v).__module__ == "stiefelsym._lazy":
                    try:
                        getattr(v, "__name__", None)
                    except Exception:   # noqa: BLE001 - a library not installed
                        pass


def _package_path() -> list[str]:
    """The package's ``__path__`` (read from the loaded package: this module is one of its modules)."""
    return list(sys.modules["stiefelsym"].__path__)


def package_roots() -> list[Path]:
    """The directories the engine's modules are imported from: the package's, and the catalog's
    (``stiefelsym.proofs``, which an editable install may map elsewhere)."""
    import importlib.util

    roots = [Path(p) for p in _package_path()]
    try:
        spec = importlib.util.find_spec("stiefelsym.proofs")
    except (ImportError, ValueError):
        spec = None
    for p in (spec.submodule_search_locations or []) if spec is not None else []:
        roots.append(Path(p))
    out: list[Path] = []
    for r in roots:
        real = Path(os.path.realpath(r))
        if real not in out:
            out.append(real)
    return out


def engine_files(roots: list[Path] | None = None) -> dict[str, str]:
    """Path -> digest of every file under the package's directories (sources, byte code, data; a symbolic
    link by its target), directories not followed through links."""
    out: dict[str, str] = {}
    for root in package_roots() if roots is None else roots:
        for folder, dirs, files in os.walk(root, followlinks=False):
            dirs.sort()
            for name in sorted(files + [d for d in dirs if os.path.islink(os.path.join(folder, d))]):
                path = os.path.join(folder, name)
                try:
                    if os.path.islink(path):
                        out[path] = "link:" + os.readlink(path)
                        continue
                    with open(path, "rb") as f:
                        out[path] = hashlib.sha256(f.read()).hexdigest()
                except OSError as exc:
                    out[path] = f"unreadable: {exc.strerror or exc}"
    return out


def _stamp(path: str) -> str:
    """A file's identity and change stamp (inode, size, modification and status-change times, in ns): any write
    changes its status-change time, which a process cannot set back; read without reading the file."""
    try:
        st = os.lstat(path)
    except OSError as exc:
        return f"unreadable: {exc.strerror or exc}"
    return f"{st.st_ino}:{st.st_size}:{st.st_mtime_ns}:{st.st_ctime_ns}"


def path_modules(entries: list[str] | None = None) -> dict[str, str]:
    """Path -> stamp of every top-level module a later ``import name`` could load from a directory of the import
    path (``sys.path``, the working directory included where it is on it): the files with a module's suffix
    (sources, byte code, extensions) and ``.pth`` files, and the packages by their ``__init__``.  A module the
    verifying process imports only after a claims file's child ran (a library the engine imports lazily) is
    found through this path: a file of that name put into a directory before the library's own shadows it
    (what lies deeper inside a library's own folder is not looked at)."""
    import importlib.machinery

    suffixes = tuple(importlib.machinery.all_suffixes()) + (".pth",)
    out: dict[str, str] = {}
    seen: set[str] = set()
    for entry in sys.path if entries is None else entries:
        folder = os.path.realpath(entry or os.getcwd())
        if folder in seen or not os.path.isdir(folder):
            continue
        seen.add(folder)
        try:
            names = sorted(os.listdir(folder))
        except OSError as exc:
            out[folder] = f"unreadable: {exc.strerror or exc}"
            continue
        for name in names:
            path = os.path.join(folder, name)
            if name.endswith(suffixes) and not os.path.isdir(path):
                out[path] = "link:" + os.readlink(path) if os.path.islink(path) else _stamp(path)
            elif name.isidentifier() and os.path.isdir(path):
                for init in ("__init__" + x for x in suffixes if x != ".pth"):
                    if os.path.isfile(os.path.join(path, init)):
                        out[os.path.join(path, init)] = _stamp(os.path.join(path, init))
    return out


def changed_files(before: dict[str, str], after: dict[str, str]) -> list[str]:
    """The files added, removed or changed between two :func:`engine_files`."""
    return sorted(p for p in set(before) | set(after) if before.get(p) != after.get(p))


# --------------------------------------------------------------------------- the processes left behind

def _prctl():
    if not sys.platform.startswith("linux"):
        return None
    try:
        import ctypes
        return ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError, ImportError):
        return None


def _table() -> dict[int, tuple[int, str]]:
    """pid -> (parent pid, state) of every process in /proc."""
    out: dict[int, tuple[int, str]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as f:
                stat = f.read().decode("ascii", "replace")
        except OSError:
            continue
        fields = stat.rpartition(")")[2].split()     # the command name (in parentheses) may hold anything
        if len(fields) >= 2 and fields[1].lstrip("-").isdigit():
            out[int(entry)] = (int(fields[1]), fields[0])
    return out


class Confined:
    """Everything a child forked inside ``with Confined() as c:`` starts stays this process's descendant
    (a subreaper, where the platform has one); :meth:`end_the_rest` kills it all.  Children this process had
    before (and their descendants) are left alone."""

    def __init__(self) -> None:
        self.prctl = _prctl()
        self.active = False
        self.me = os.getpid()
        self.before: set[int] = set()

    def __enter__(self) -> Confined:
        if self.prctl is not None and os.path.isdir("/proc/self"):
            try:
                self.before = {p for p, (pp, _) in _table().items() if pp == self.me}
                self.active = self.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0
            except OSError:
                self.active = False
        return self

    def __exit__(self, *exc: object) -> None:
        if self.active:
            try:
                self.end_the_rest()
            finally:
                self.prctl(PR_SET_CHILD_SUBREAPER, 0, 0, 0, 0)
                self.active = False

    def descendants(self) -> dict[int, tuple[int, str]]:
        """pid -> (parent, state) of the processes under this one that are not under a child it had before."""
        table = _table()
        out = {}
        for pid in table:
            q, steps = pid, 0
            while q in table and steps < 1 << 16:
                if q in self.before:
                    break
                parent = table[q][0]
                if parent == self.me:
                    out[pid] = table[pid]
                    break
                q, steps = parent, steps + 1
        return out

    def end_the_rest(self) -> None:
        """Kill every process the confined children left (and reap those re-parented here); raises
        :class:`ProcessesLeft` when some still run after :data:`END_SECONDS`."""
        if not self.active:
            return
        deadline = time.monotonic() + END_SECONDS
        while True:
            found = self.descendants()
            if not found:
                return
            for pid, (_, state) in found.items():
                if state not in ("Z", "X"):
                    try:
                        os.kill(pid, signal.SIGKILL)
                    except OSError:
                        pass
            for pid, (parent, _) in found.items():
                if parent == self.me:
                    try:
                        os.waitpid(pid, os.WNOHANG)
                    except ChildProcessError:
                        pass
            if time.monotonic() > deadline:
                raise ProcessesLeft(f"{len(found)} process(es) a claims file started could not be ended "
                                    f"(pids {', '.join(map(str, sorted(found)[:8]))})")
            time.sleep(0.002)
