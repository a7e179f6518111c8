"""A fresh, confined interpreter for a user's claims file.

:func:`stiefelsym.run.userfile.load_claims_isolated` never lets a claims file run in a process that knows the
run: :func:`run` *spawns* (never forks) ``python -I -B -c BOOT`` (``-s -P`` for ``-I`` from Python 3.11) with a neutral argv, a minimal environment
(a fixed hash seed, no ``STIEFELSYM_*``, no user variable), its standard input carrying only what the phase needs (the file's
path, the search path of the package, the engine's tracing budgets (never the run's), and in the second
phase one size per line on descriptor 3, each read by a process of its own), and its standard output
carrying the answer.  So the process that imports the file holds no
parsed option, no command line and no environment of the run in its memory.

Where the platform allows it (Linux, util-linux ``unshare``, user namespaces), the interpreter runs in new
user, pid, mount, network and IPC namespaces with its own ``/proc`` (the verifying process and every process
outside are not visible: no ``/proc/<ppid>/cmdline``), and, before anything of the file is read, it makes
every mount read-only, mounts a private tmpfs on ``/tmp`` (what the interpreter reads there bound
read-only into it: the claims file's folder, or the file alone when it lies in /tmp itself, never the host's
whole /tmp; see :func:`_keep`), enters its working directory again by path in that view and locks that view by entering a user namespace of its own (mounts inherited
from a more privileged namespace cannot be made writable again, nor unmounted, from a less privileged one).
The private ``/tmp`` is made read-only too once it holds what the interpreter reads: the file then writes nowhere
(but the pipes it was given), reaches no network and no process outside, and when the namespace's first process
ends the kernel ends every process in it.  Between two jobs of the interpreter (the import, each claim, each size
of the second phase) the processes and System V IPC objects the job left are ended
(:class:`stiefelsym.run.userfile._Between`) and no POSIX message queue can be made: nothing one claim or size saw
reaches the next.

Where that is not available (not Linux, no ``unshare``, user namespaces disabled, ``STIEFELSYM_CONFINE=spawn``)
the same interpreter is spawned without namespaces (:data:`SPAWN`): it still holds nothing of the run, but
it can read ``/proc/<ppid>/cmdline``, write with the user's rights, reach the network and connect to any Unix
socket the user can (only the descriptors it would inherit are closed, as in namespaces); every record of
such a file says so (:func:`note`).  The verifying process is then made not dumpable before the first such
interpreter, so that a process of the same user cannot read or write its memory (process_vm_writev, ptrace;
a process of root can).

The first line the interpreter writes is its confinement, written before anything of the file runs: a
setup that fails there falls back to the plain spawn, a file cannot ask for that fallback.
"""
from __future__ import annotations

import ctypes
import errno
import json
import math
import os
import select
import shutil
import subprocess
import signal
import stat
import sys
import threading
import time
from typing import Any, Callable

#: the confinements, in the order they are tried
NAMESPACES = "namespaces"
SPAWN = "spawn"
#: what a record of a claims file says about the process that traced it
NOTES = {
    NAMESPACES: "",
    SPAWN: ("claims file traced in a spawned interpreter without namespaces (none available here): it could "
            "read the verifying process's command line in /proc, write with the user's rights, and reach the "
            "network and the Unix sockets of the user's processes"),
}
#: $STIEFELSYM_CONFINE=spawn: no namespaces even where they are available (read by the verifying process only)
CONFINE_ENV = "STIEFELSYM_CONFINE"
#: the private /tmp of a confined interpreter
TMP_OPTIONS = b"size=64m,mode=1777"
#: where the unshare program is looked for (not the user's PATH)
SYSTEM_PATH = "/usr/bin:/bin:/usr/sbin:/sbin"

#: the interpreter's program: this module loaded from its file alone (the first line of standard input: its
#: path and the package's search path), then host(), which confines the process before the package (numpy and
#: its threads: a threaded process cannot enter a user namespace) is imported
BOOT = ("import sys,json,importlib.util as u;b=json.loads(sys.stdin.buffer.readline());sys.path[:0]=b[1];"
        "s=u.spec_from_file_location('stiefelsym_sandbox_host',b[0]);m=u.module_from_spec(s);"
        "s.loader.exec_module(m);m.host()")

_available: dict[str, bool] = {}


class SandboxError(RuntimeError):
    """The confined interpreter could not be set up (raised inside it, before the file is read)."""


def note(confinement: str) -> str:
    return NOTES.get(confinement, f"claims file traced under an unknown confinement {confinement!r}")


# --------------------------------------------------------------------------- the verifying process

def _unshare() -> str | None:
    if not sys.platform.startswith("linux") or os.environ.get(CONFINE_ENV, "") == SPAWN:
        return None
    if _available.get(NAMESPACES) is False:
        return None
    return shutil.which("unshare", path=SYSTEM_PATH)


def namespaces_available() -> bool:
    """Whether a claims file would be traced in namespaces here: Linux, ``unshare`` found, not switched off
    by $STIEFELSYM_CONFINE=spawn, and a user + pid + mount + net namespace can be made (tried once)."""
    unshare = _unshare()
    if unshare is None:
        return False
    out = subprocess.run([unshare, "--user", "--map-root-user", "--pid", "--fork", "--mount", "--mount-proc",
                          "--net", "--ipc", "true"], capture_output=True, timeout=60)
    return out.returncode == 0


def _search_path(file: str | None = None) -> list[str]:
    """The directory the loaded package comes from, then this process's search path (absolute), then the
    claims file's own folder (as Python puts a script's folder on its path: a claims file imports the
    helper modules next to it; last, so that a module there shadows neither the engine nor a library).  Not
    /tmp itself, which is shared: of /tmp the interpreter sees only what :func:`_keep` lists."""
    pkg = os.path.dirname(os.path.dirname(os.path.abspath(sys.modules["stiefelsym"].__file__ or "")))
    out = [pkg]
    for p in sys.path:
        if p and os.path.isabs(p) and p not in out:
            out.append(p)
    if file:
        folder = os.path.dirname(os.path.realpath(file))
        if folder not in out and folder != os.path.realpath("/tmp"):
            out.append(folder)
    return out


def _sockets() -> list[str]:
    """The paths of the Unix sockets bound in the file system as this process's network namespace lists them
    (``/proc/net/unix``: every socket a process of this namespace bound to a path, the verifying process's own
    included), that are sockets now: a confined interpreter masks each (:func:`lock_down`), since a socket
    file can be connected to on a read-only mount.  Not listed: a socket bound by a process of another network
    namespace, or after this list is taken, and one bound to a relative path."""
    try:
        with open("/proc/net/unix", "rb") as f:
            lines = f.read().decode("utf-8", "surrogateescape").splitlines()[1:]
    except OSError:
        return []
    out = set()
    for line in lines:
        fields = line.split(None, 7)
        if len(fields) == 8 and fields[7].startswith("/"):
            try:
                if stat.S_ISSOCK(os.lstat(fields[7]).st_mode):
                    out.add(fields[7])
            except OSError:
                continue
    return sorted(out)      # every one: a mask that cannot be mounted fails the setup (then the plain spawn, stated)


#: the interpreter's isolation: -I (no PYTHON* variable, no user site, no script folder on the path), written as
#: -s -P where Python has -P (3.11) so that PYTHONHASHSEED, the one PYTHON* variable of :func:`_environment`, is read:
#: the hash of a string is then the same in every run, and a claim whose graph depends on it (on the order of a set of
#: names) gives the same graph, digest and verdict each time (stop 85's sweep: a file that branched on hash() was
#: refuted in one run and passed in the next, with the same --seed)
_ISOLATED = ("-s", "-P") if sys.version_info >= (3, 11) else ("-I",)
HASH_SEED = "0"


def _environment() -> dict[str, str]:
    return {"PATH": SYSTEM_PATH, "LC_ALL": "C.UTF-8", "HOME": "/tmp", "PYTHONHASHSEED": HASH_SEED}


def run(config: dict[str, Any], capture: int, seconds: float, requests: bytes = b"",
        before_plain: Callable[[], None] | None = None,
        import_seconds: float | None = None, beat_seconds: float | None = None) -> tuple[bytes | None, str]:
    """``config`` (JSON) to a fresh interpreter running :func:`host`, its answer back: (bytes, or None when it
    died or ran out of ``seconds``; the confinement used).  What it prints goes to ``capture``.  The
    namespaces are given up (for this process's later files too) only when the interpreter did not write its
    confinement line, i.e. before anything of the file ran.  ``before_plain`` is called before an interpreter is
    spawned without namespaces (:data:`SPAWN`), and only then: in namespaces the file writes nowhere on the host's
    file system (:func:`lock_down`), without them it writes with the user's rights (the caller's preparation for
    that, :func:`stiefelsym.run.userfile.load_claims_isolated`: the whole package imported first).
    ``import_seconds``: each import of the file must have ended (its :data:`IMPORTED` line written) within that
    many seconds of the interpreter's confinement line or of its last answer line, else the interpreter is
    killed (None) -- kept here, in the verifying process, because code of the file that holds the interpreter's
    lock in C also stops the file's own watch (:func:`stiefelsym.run.userfile._watched`).  ``beat_seconds``: once
    an import has ended, the tracing writes a :data:`BEAT` line after each function traced at a size (each has its
    own budget in the tracing process); the interpreter is killed when neither that line nor an answer has come
    within that many seconds of the last (a thread of the file that holds the lock in C stops the tracing process
    too).  The IMPORTED and BEAT lines are not part of the answer returned."""
    unshare = _unshare()
    if unshare is not None:
        raw, status = _spawn(config, capture, seconds, unshare, requests, import_seconds, beat_seconds)
        head = _line(NAMESPACES)
        if raw.startswith(head):
            _available[NAMESPACES] = True
            return (_answer(raw[len(head):]) if status == 0 else None), NAMESPACES
        if _available.get(NAMESPACES) is None:
            # whether namespaces work here is asked with a file of no claims in a folder of the engine's making,
            # never read off this file's failure: what the file controls (its path, its folder's name) must not
            # be able to ask for the fallback without them
            _available[NAMESPACES] = _namespaces_work(config, unshare)
        if _available[NAMESPACES]:          # they work: this file's process ended before its line
            return None, NAMESPACES
    if before_plain is not None:
        before_plain()
    raw, status = _spawn(config, capture, seconds, None, requests, import_seconds, beat_seconds)
    head = _line(SPAWN)
    return (_answer(raw[len(head):]) if status == 0 and raw.startswith(head) else None), SPAWN


#: the line the interpreter writes (before its answer) when an import of the file has ended
IMPORTED = b'{"imported": true}\n'
#: the line the interpreter writes (before its answer) each time the tracing of a claim's function (or of its
#: metadata) at one size has ended
BEAT = b'{"traced": true}\n'
_MARKERS = (IMPORTED[:-1], BEAT[:-1])


def _answer(raw: bytes) -> bytes:
    """What the interpreter wrote after its confinement line, without its IMPORTED and BEAT lines."""
    if IMPORTED not in raw and BEAT not in raw:
        return raw
    return b"\n".join(line for line in raw.split(b"\n") if line not in _MARKERS)


def _namespaces_work(config: dict[str, Any], unshare: str) -> bool:
    """Whether an interpreter confined in namespaces starts here: one spawned on an empty claims file in a fresh
    folder writes its confinement line."""
    import tempfile
    with tempfile.TemporaryDirectory(prefix="stiefelsym-probe-") as folder:
        probe = os.path.join(folder, "no_claims.py")
        with open(probe, "w", encoding="utf-8") as f:
            f.write('"""No claims: whether the confinement starts."""\n')
        null = os.open(os.devnull, os.O_WRONLY)
        try:
            raw, _status = _spawn(dict(config, file=probe, second=False), null, PROBE_SECONDS, unshare)
        finally:
            os.close(null)
    return raw.startswith(_line(NAMESPACES))


#: seconds the probe of :func:`_namespaces_work` may take
PROBE_SECONDS = 60.0


def _line(confinement: str) -> bytes:
    return json.dumps({"confined": confinement}).encode() + b"\n"


def _spawn(config: dict[str, Any], capture: int, seconds: float, unshare: str | None,
           requests: bytes = b"", import_seconds: float | None = None,
           beat_seconds: float | None = None) -> tuple[bytes, int | None]:
    """Spawn the interpreter (in namespaces when ``unshare`` is given): what it wrote, and its wait status
    (None: it ran out of time, or could not be started)."""
    from stiefelsym.run.confine import Confined
    argv = [sys.executable, *_ISOLATED, "-B", "-c", BOOT]
    if unshare is not None:
        argv = [unshare, "--user", "--map-root-user", "--pid", "--fork", "--kill-child", "--mount",
                "--mount-proc", "--net", "--ipc", "--propagation", "private"] + argv
    conf = dict(config, confine=unshare is not None, sockets=_sockets() if unshare is not None else [])
    stdin = (json.dumps([os.path.abspath(__file__), _search_path(config.get("file"))]) + "\n"
             + json.dumps(conf)).encode()
    with Confined():
        r0, w0 = os.pipe()
        r1, w1 = os.pipe()
        r3, w3 = _pipe_above(3)
        try:
            pid = os.posix_spawn(argv[0], argv, _environment(), setsid=True,
                                 file_actions=[(os.POSIX_SPAWN_DUP2, r0, 0), (os.POSIX_SPAWN_DUP2, w1, 1),
                                               (os.POSIX_SPAWN_DUP2, capture, 2), (os.POSIX_SPAWN_DUP2, r3, 3)])
        except OSError:
            for fd in (r0, w0, r1, w1, r3, w3):
                os.close(fd)
            return b"", None
        for fd in (r0, w1, r3):
            os.close(fd)
        writer = threading.Thread(target=_write_all, args=(w3, requests), daemon=True)
        writer.start()      # (read by the interpreter only after its forks: never in the way of the answer)
        _write_all(w0, stdin)
        try:
            chunks, status = _read_until_exit(pid, r1, seconds, import_seconds, beat_seconds)
        finally:
            _kill_group(pid)
    return b"".join(chunks), status


def _pipe_above(low: int) -> tuple[int, int]:
    """A pipe both of whose ends are above ``low`` (a duplication onto itself would keep close-on-exec)."""
    r, w = os.pipe()
    if min(r, w) > low:
        return r, w
    r2, w2 = os.dup(r) if r <= low else r, os.dup(w) if w <= low else w
    for fd, new in ((r, r2), (w, w2)):
        if new != fd:
            os.close(fd)
    return _pipe_above(low) if min(r2, w2) <= low else (r2, w2)


def _write_all(fd: int, data: bytes) -> None:
    """``data`` to ``fd``, then ``fd`` closed (a reader that is gone ends the writing)."""
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
    except OSError:
        pass
    finally:
        os.close(fd)


def _read_until_exit(pid: int, rfd: int, seconds: float,
                     import_seconds: float | None = None,
                     beat_seconds: float | None = None) -> tuple[list[bytes], int | None]:
    """What the child ``pid`` writes to ``rfd`` until it has exited (and all it wrote is read), and its wait
    status; None after ``seconds``, or when ``import_seconds`` passed after a line that an import of the file
    follows (the confinement line, an answer line) without its IMPORTED line (:func:`run`).  ``rfd`` is closed."""
    chunks: list[bytes] = []
    deadline = time.monotonic() + seconds
    lines = _Lines(import_seconds, beat_seconds)
    pidfd = -1
    if hasattr(os, "pidfd_open"):
        try:
            pidfd = os.pidfd_open(pid)
        except OSError:
            pidfd = -1
    eof = False
    try:
        os.set_blocking(rfd, False)
        while True:
            now = time.monotonic()
            left = min(deadline, lines.deadline) - now
            if left <= 0:
                return chunks, None
            watch = ([] if eof else [rfd]) + ([pidfd] if pidfd >= 0 else [])
            ready, _, _ = select.select(watch, [], [], left if pidfd >= 0 else min(left, 0.02))
            if rfd in ready:
                try:
                    chunk = os.read(rfd, 1 << 16)
                except BlockingIOError:
                    chunk = None
                if chunk:
                    chunks.append(chunk)
                    lines.read(chunk)
                    continue
                eof = eof or chunk == b""
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                while True:             # what it wrote before it exited is all in the pipe
                    chunk = _read_some(rfd)
                    if not chunk:
                        return chunks, status
                    chunks.append(chunk)
    finally:
        os.close(rfd)
        if pidfd >= 0:
            os.close(pidfd)


class _Lines:
    """The deadline of :func:`_read_until_exit` from the lines read so far: after the confinement line and after
    each answer line an import of the file follows (one per process that traces it), which must write its IMPORTED
    line within ``seconds``; after it, the next BEAT line, or more of the answer, must come within ``beat`` of the
    last bytes read (None: no deadline, each trace has its own in the tracing process).  Each byte is looked at
    once: of a line only its first bytes are kept, as many as a marker has (an answer is megabytes long)."""

    _LONGEST = max(len(m) for m in _MARKERS)

    def __init__(self, seconds: float | None, beat: float | None = None) -> None:
        self.seconds, self.beat, self.deadline = seconds, beat, math.inf
        self.head, self.blank, self.beating = b"", True, False

    def read(self, chunk: bytes) -> None:
        if self.seconds is None and self.beat is None:
            return
        start = 0
        while True:
            k = chunk.find(b"\n", start)
            piece = chunk[start:] if k < 0 else chunk[start:k]
            if len(self.head) <= self._LONGEST:
                self.head += piece[:self._LONGEST + 1 - len(self.head)]
            self.blank = self.blank and not piece.strip()
            if k < 0:
                break
            self._line_ended()
            start = k + 1
        if self.beating and self.beat is not None and chunk:
            self.deadline = time.monotonic() + self.beat      # bytes of the answer, or of a line, came

    def _line_ended(self) -> None:
        if self.head in _MARKERS:
            self.beating = True
            self.deadline = math.inf if self.beat is None else time.monotonic() + self.beat
        elif not self.blank:      # the confinement line, or an answer: the next import starts now
            self.beating = False
            self.deadline = math.inf if self.seconds is None else time.monotonic() + self.seconds
        self.head, self.blank = b"", True


def _read_some(fd: int) -> bytes:
    try:
        return os.read(fd, 1 << 16)
    except BlockingIOError:
        return b""


def _kill_group(pid: int) -> None:
    """Kill the process group ``pid`` (the interpreter and what it started in its session) and reap ``pid``."""
    try:
        os.killpg(pid, signal.SIGKILL)
    except OSError:
        pass
    try:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
    except (ProcessLookupError, ChildProcessError):
        pass


# --------------------------------------------------------------------------- the interpreter

MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC = 1, 2, 4, 8
MS_REMOUNT, MS_NOATIME, MS_NODIRATIME, MS_BIND = 32, 1024, 2048, 4096
MS_REC, MS_PRIVATE, MS_RELATIME, MS_STRICTATIME = 1 << 14, 1 << 18, 1 << 21, 1 << 24
PR_CAPBSET_DROP, PR_SET_NO_NEW_PRIVS, PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL = 24, 38, 47, 4
_LINUX_CAPABILITY_VERSION_3 = 0x20080522
_FLAGS = {"nosuid": MS_NOSUID, "nodev": MS_NODEV, "noexec": MS_NOEXEC, "noatime": MS_NOATIME,
          "nodiratime": MS_NODIRATIME, "relatime": MS_RELATIME, "strictatime": MS_STRICTATIME}
def _libc() -> Any:
    return ctypes.CDLL(None, use_errno=True)


def _mount(libc: Any, source: bytes | None, target: bytes, fstype: bytes | None, flags: int,
           data: bytes | None) -> None:
    if libc.mount(source, target, fstype, ctypes.c_ulong(flags), data) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"mount {target.decode(errors='replace')}: {os.strerror(err)}")


def _unescape(field: str) -> bytes:
    """A path of /proc/self/mountinfo (spaces and the like as \\ooo)."""
    out, i = bytearray(), 0
    raw = field.encode("utf-8", "surrogateescape")
    while i < len(raw):
        if raw[i:i + 1] == b"\\" and raw[i + 1:i + 4].isdigit():
            out.append(int(raw[i + 1:i + 4], 8))
            i += 4
        else:
            out.append(raw[i])
            i += 1
    return bytes(out)


def _mounts() -> list[tuple[bytes, int, str]]:
    """(mount point, its per-mount flags, file system type) of every mount of this namespace."""
    out = []
    with open("/proc/self/mountinfo") as f:
        for line in f:
            left, _, right = line.partition(" - ")
            fields = left.split()
            if len(fields) < 6:
                continue
            flags = 0
            for opt in fields[5].split(","):
                flags |= _FLAGS.get(opt, 0)
            out.append((_unescape(fields[4]), flags, (right.split() or ["?"])[0]))
    return out


def lock_down(keep: list[str], sockets: list[str] | None = None) -> None:
    """In fresh user + mount namespaces (as root there), before any thread is started: every mount read-only,
    without devices and set-uid programs, a private tmpfs on /tmp (``keep``, folders and files under /tmp,
    bound read-only into it: see :func:`_keep`), an empty file mounted read-only over each of the Unix
    sockets ``sockets`` (:func:`_sockets`) that is one in this view, then every capability dropped for good (bounding set,
    permitted, effective, ambient; no new privileges), so that no mount can be changed again, in this namespace
    or in one the file creates (there the mounts made here are locked).  Raises :class:`SandboxError` when any
    step fails."""
    libc = _libc()
    try:
        _mount(libc, None, b"/", None, MS_REC | MS_PRIVATE, None)
        for target, flags, _fstype in _mounts():
            try:
                _mount(libc, None, target, None, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NODEV | MS_NOSUID | flags,
                       None)
            except OSError as exc:
                if not os.path.ismount(target) and exc.errno == errno.EINVAL:
                    continue        # a mount hidden under another one (its mount point resolves to that one)
                raise
        # held before the tmpfs hides them; a folder is bound with what is mounted below it (never /tmp itself,
        # whose mounts below would then include the private tmpfs), a file alone
        held = [(p, os.path.isdir(p), os.open(p, os.O_PATH | (os.O_DIRECTORY if os.path.isdir(p) else 0)))
                for p in keep]
        _mount(libc, b"tmpfs", b"/tmp", b"tmpfs", MS_NOSUID | MS_NODEV, TMP_OPTIONS)
        for target, folder, fd in held:
            os.makedirs(target if folder else os.path.dirname(target), exist_ok=True)
            if not folder:
                os.close(os.open(target, os.O_WRONLY | os.O_CREAT, 0o444))     # the mount point of a file
            path = os.fsencode(target)      # (a name that is not UTF-8 comes back from the OS as it was)
            _mount(libc, f"/proc/self/fd/{fd}".encode(), path, None, MS_BIND | (MS_REC if folder else 0), None)
            _mount(libc, None, path, None, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV, None)
            os.close(fd)
        _mask(libc, sockets or [])
        # the private /tmp read-only too, once what it holds is in place: no file the interpreter or its
        # children write can carry what one claim or size saw to the next (every other mount is read-only)
        _mount(libc, None, b"/tmp", None, MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV, TMP_OPTIONS)
        _drop_capabilities(libc)
        if libc.mount(None, b"/", None, ctypes.c_ulong(MS_REMOUNT | MS_BIND), None) == 0:
            raise OSError(0, "the root could be made writable again")
    except (OSError, ValueError) as exc:
        raise SandboxError(str(exc)) from None


def _mask(libc: Any, sockets: list[str]) -> None:
    """An empty file mounted read-only over each of ``sockets`` that is a Unix socket in this view: a connection
    to it is refused (it is not a socket), and no mount can be changed once the capabilities are dropped."""
    blank = "/tmp/.stiefelsym-masked-socket"     # kept (empty, mode 0): the private /tmp is then made read-only,
    os.close(os.open(blank, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0))    # which a deleted file still mounted forbids
    for path in sockets:
        try:
            if not stat.S_ISSOCK(os.lstat(path).st_mode):
                continue
        except OSError:
            continue
        target = path.encode("utf-8", "surrogateescape")
        _mount(libc, blank.encode(), target, None, MS_BIND, None)
        _mount(libc, None, target, None, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC,
               None)


class _CapHeader(ctypes.Structure):
    _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]


class _CapData(ctypes.Structure):
    _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32), ("inheritable", ctypes.c_uint32)]


def _drop_capabilities(libc: Any) -> None:
    """Every capability of this (single-threaded) process dropped, and none to be gained by exec."""
    def prctl(*args: int) -> int:
        return int(libc.prctl(*[ctypes.c_ulong(a) for a in args]))
    for cap in range(64):
        if prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0 and ctypes.get_errno() != errno.EINVAL:
            err = ctypes.get_errno()
            raise OSError(err, f"dropping capability {cap}: {os.strerror(err)}")
    prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0)
    if prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        raise OSError(ctypes.get_errno(), "no_new_privs")
    header, data = _CapHeader(_LINUX_CAPABILITY_VERSION_3, 0), (_CapData * 2)()
    if libc.capset(ctypes.byref(header), data) != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"capset: {os.strerror(err)}")


def _keep(path: str) -> list[str]:
    """What the interpreter reads under /tmp (hidden by the private tmpfs otherwise), outermost only: the folders
    under /tmp of the claims file, of the interpreter and of the search path (the package itself may be a copy
    there), each whole; never /tmp itself: of /tmp, the claims file when it lies there, and when /tmp is on the
    search path (a command run from /tmp with ``python -m``) what an import can load from it, the files of a
    module's suffix and the folders of a package (with an ``__init__``; a namespace package there is not seen),
    a symbolic link as its target."""
    import importlib.machinery
    tmp = os.path.realpath("/tmp")
    file = os.path.realpath(path)
    here = [os.path.dirname(file), os.path.dirname(os.path.realpath(sys.executable)), sys.prefix, sys.base_prefix]
    found = [p for p in (os.path.realpath(x) for x in here + [x for x in sys.path if x])
             if p.startswith(tmp + os.sep) and os.path.isdir(p)]
    if os.path.dirname(file) == tmp and os.path.isfile(file):
        found.append(file)
    if any(os.path.realpath(x) == tmp for x in sys.path if x):
        suffixes = tuple(importlib.machinery.all_suffixes())
        for name in sorted(os.listdir(tmp)):
            entry = os.path.join(tmp, name)
            if name.endswith(suffixes) and os.path.isfile(entry):
                found.append(entry)
            elif name.isidentifier() and os.path.isdir(entry) and any(
                    os.path.isfile(os.path.join(entry, "__init__" + x)) for x in suffixes):
                found.append(entry)
    out: list[str] = []
    for p in sorted(set(found)):
        if not any(p == q or p.startswith(q + os.sep) for q in out):
            out.append(p)
    return out


def _close_inherited(keep: set[int]) -> None:
    """Every file descriptor above standard error closed but ``keep`` (the answer's pipe, the requests'), before
    anything of the file runs: what the verifying process's own caller left inheritable (a socket, a pipe to a
    service) is not the file's."""
    try:
        fds = [int(x) for x in os.listdir("/proc/self/fd")]
    except OSError:
        fds = list(range(3, 1 << 16))
    for fd in fds:
        if fd > 2 and fd not in keep:
            try:
                os.close(fd)
            except OSError:
                pass


def _enter(folder: str) -> None:
    """The working directory entered again by its path in the confined view (a directory entered before the
    mounts would still see what they hide: the host's /tmp through a working directory there), or / when that
    path is not in the view."""
    try:
        os.chdir(folder)
    except OSError:
        os.chdir("/")


#: whether this process is the interpreter of a claims file confined in namespaces (set by :func:`host`): then its
#: System V IPC objects are its own IPC namespace's, which :func:`stiefelsym.run.userfile` clears between jobs
CONFINED = False


def _no_message_queues() -> None:
    """No POSIX message queue can be made by the file (RLIMIT_MSGQUEUE 0): a queue outlives the process that made
    it, and nothing lists the queues of a namespace to clear them between jobs."""
    try:
        import resource
        resource.setrlimit(resource.RLIMIT_MSGQUEUE, (0, 0))
    except (ImportError, AttributeError, ValueError, OSError):
        pass


def host() -> None:
    """The spawned interpreter: read the configuration, confine itself, trace the file, write the answer."""
    config = json.loads(sys.stdin.buffer.read())
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.close(null)
    answer = os.dup(1)
    requests = 3 if config.get("second") else -1     # the second phase's requests (sandbox.run)
    _close_inherited({answer, requests})
    os.dup2(2, 1)       # whatever the file prints goes to the capture, like its standard error
    sys.stdout = open(1, "w", closefd=False, errors="replace")

    def send(data: bytes) -> None:
        view = memoryview(data)
        while view:
            view = view[os.write(answer, view):]
    confined = bool(config.pop("confine"))
    if confined:
        try:
            here = os.getcwd()
            lock_down(_keep(config["file"]), config.pop("sockets"))
            _enter(here)
        except BaseException as exc:    # noqa: BLE001 - whatever failed, nothing of the file runs unconfined here
            sys.stderr.write(f"stiefelsym: no confinement for the claims file ({type(exc).__name__}: {exc})\n")
            sys.stderr.flush()
            os._exit(3)
    global CONFINED
    CONFINED = confined
    _no_message_queues()
    send(_line(NAMESPACES if confined else SPAWN))     # before anything of the file runs
    import importlib
    userfile = importlib.import_module("stiefelsym.run.userfile")
    if os.path.dirname(os.path.realpath(userfile.__file__)) != os.path.dirname(os.path.realpath(__file__)):
        sys.stderr.write(f"stiefelsym: the engine was imported from {userfile.__file__}, not next to {__file__}\n")
        sys.stderr.flush()
        os._exit(4)
    # this module runs here under another name (BOOT loads it from its file): the engine reads the confinement
    # from the package's module (userfile: the IPC objects removed between jobs, a PID namespace per job)
    importlib.import_module("stiefelsym.run.sandbox").CONFINED = confined
    if requests < 0:
        data = userfile._tracer(config["file"], None, float(config["timeout"]), config.get("memory"), send)
    else:       # each of its children writes its own answer
        userfile._tracer_by_size(config["file"], requests, answer, float(config["timeout"]), config.get("memory"))
        data = b""
    send(data)
    os._exit(0)
