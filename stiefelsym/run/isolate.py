"""Run a computation in a forked child with a hard time limit.

Symbolic expansion inside symengine's C++ code cannot be interrupted by a
signal handler; a child process can always be killed.  Where fork is not
available the computation runs in-process (with the signal-based limit only).
"""
from __future__ import annotations

import gc
import os
import pickle
import select
import signal
import sys
import time
from typing import Any, Callable, NoReturn


class HardTimeout(Exception):
    """The child exceeded its time limit and was killed."""


class ChildError(Exception):
    """The computation raised in the child; the message says what and where."""


class ChildDied(ChildError):
    """The child ended without a result: it ran out of memory (MemoryError, or a native allocation
    that failed and aborted) or was killed; the message says how it ended."""


def _child(rfd: int, wfd: int, parent: int, prctl: Any, payload: Callable[[], bytes],
           setup: Callable[[], None] | None = None) -> NoReturn:
    """The whole life of a forked child: close the pipe's read end, ``setup()``, die with the parent (which
    may already be gone), write ``payload()`` into the pipe and exit without running the parent's cleanup."""
    os.close(rfd)
    try:
        if setup is not None:
            setup()
        if prctl:
            prctl(1, signal.SIGKILL)     # PR_SET_PDEATHSIG: die with the parent, never outlive it
            if os.getppid() != parent:
                os._exit(0)
        data = payload()
        with os.fdopen(wfd, "wb") as pipe:
            pipe.write(data)
    finally:
        os._exit(0)


def run_isolated(fn: Callable[[], Any], seconds: float, describe: Callable[[BaseException], str],
                 cpu_seconds: float | None = None) -> Any:
    """fn() in a forked child, killed after ``seconds``; its exceptions come back as ChildError.

    ``cpu_seconds``: the child is stopped (HardTimeout) once it has used that much CPU time, whatever the wall
    time it took (RLIMIT_CPU): a limit that decides which result a run gives is then the computation's, not the
    machine's load (``seconds`` stays the wall limit behind it)."""
    if not hasattr(os, "fork"):
        return fn()
    from stiefelsym.run.pool import _death_signal_setup
    prctl = _death_signal_setup()
    parent = os.getpid()
    rfd, wfd = os.pipe()
    err, out = _capture(), _capture()
    _flush()       # nothing of this process's buffers is left for the child to write a second time
    gc.freeze()    # keep the parent's objects out of the child's collections (fewer copied pages)
    pid = os.fork()
    if pid == 0:   # the child: compute, send, exit without running the parent's cleanup
        def redirect() -> None:
            os.dup2(err, 2)     # its standard error and output, read by the parent (see _said): flint
            os.dup2(out, 1)     # writes why it aborts to the standard output
            os.close(err)
            os.close(out)
            if cpu_seconds is not None:
                import math
                import resource
                soft = max(1, math.ceil(cpu_seconds))
                resource.setrlimit(resource.RLIMIT_CPU, (soft, soft + 1))   # SIGXCPU at soft, SIGKILL at hard

        def payload() -> bytes:
            try:
                data = pickle.dumps(("ok", fn()))
            except MemoryError as exc:
                data = pickle.dumps(("memory", describe(exc)))
            except BaseException as exc:  # noqa: BLE001 - everything goes back to the parent
                data = pickle.dumps(("error", describe(exc)))
            _flush()            # what it printed, into the files the parent reads (os._exit flushes nothing)
            return data
        _child(rfd, wfd, parent, prctl, payload, redirect)
    os.close(wfd)
    gc.unfreeze()
    try:
        data = read_pipe(rfd, seconds, lambda: _kill(pid))
        if data is not None:
            _, status, usage = os.wait4(pid, 0)
    finally:
        said, printed = _said(err), _said(out)
    if data is None:
        _forward(said, printed)
        raise HardTimeout()
    if not data:
        if cpu_seconds is not None and os.WIFSIGNALED(status) and (os.WTERMSIG(status) == signal.SIGXCPU or (
                os.WTERMSIG(status) == signal.SIGKILL and usage.ru_utime + usage.ru_stime >= cpu_seconds)):
            _forward(said, printed)
            raise HardTimeout()
        raise ChildDied(f"the child process died ({how_it_ended(status)}{_last_words(said + printed)})")
    kind, value = pickle.loads(data)
    if kind == "memory":        # (flint says so first: in the message, not printed)
        raise ChildDied(f"the child process ran out of memory ({value}{_last_words(said + printed)})")
    _forward(said, printed)
    if kind == "error":
        raise ChildError(value)
    return value


def in_background(fn: Callable[[], Any]) -> Callable[[], Any]:
    """fn() started in a forked child while the caller goes on; the function returned waits for the child and
    gives fn()'s value.  For a pure computation whose value is pickled back (a report's text): where fork is not
    available, or the child ends without a value, fn() is computed in this process when the value is asked for,
    so the value is the same either way."""
    if not hasattr(os, "fork"):
        return fn
    from stiefelsym.run.pool import _death_signal_setup
    prctl = _death_signal_setup()
    parent = os.getpid()
    rfd, wfd = os.pipe()
    _flush()
    gc.freeze()
    try:
        pid = os.fork()
    except OSError:
        os.close(rfd)
        os.close(wfd)
        gc.unfreeze()
        return fn
    if pid == 0:
        _child(rfd, wfd, parent, prctl, lambda: pickle.dumps(fn(), protocol=pickle.HIGHEST_PROTOCOL))
    os.close(wfd)
    gc.unfreeze()

    def value() -> Any:
        chunks = []
        try:
            while chunk := os.read(rfd, 1 << 20):
                chunks.append(chunk)
        finally:
            os.close(rfd)
            _kill(pid)
        try:
            return pickle.loads(b"".join(chunks))
        except Exception:   # noqa: BLE001 - the child ended without its value (it raised, it was killed): here then
            return fn()
    return value


def _flush() -> None:
    """Write out what Python holds in the buffers of the standard output and error."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (AttributeError, OSError, ValueError):
            pass


#: the longest line of a dead child's standard error quoted in its ChildDied message
MESSAGE_CHARS = 200


def _capture() -> int:
    """A file descriptor of an anonymous file for a child's standard error or output (in memory where the
    platform has memfd_create)."""
    if hasattr(os, "memfd_create"):
        return os.memfd_create("stiefelsym-child-stderr")
    import tempfile
    return os.dup(tempfile.TemporaryFile().fileno())


def _said(fd: int) -> str:
    """What a child wrote to its standard error (the file of :func:`_capture`, closed here)."""
    try:
        os.lseek(fd, 0, os.SEEK_SET)
        chunks = []
        while chunk := os.read(fd, 1 << 16):
            chunks.append(chunk)
        return b"".join(chunks).decode("utf-8", "replace")
    finally:
        os.close(fd)


def _last_words(said: str) -> str:
    """The last line a child wrote to its standard error, for the message that says how it ended ("" if none)."""
    last = [line for line in said.splitlines() if line.strip()][-1:]
    return f"; its last words: {last[0].strip()[:MESSAGE_CHARS]}" if last else ""


def _forward(text: str, printed: str = "") -> None:
    """A child's standard error and output, passed on to this process's (where a run prints what claims
    print)."""
    for stream, chunk in ((sys.stdout, printed), (sys.stderr, text)):
        if chunk:
            stream.write(chunk)
            stream.flush()


def how_it_ended(status: int) -> str:
    """A wait status in words: the signal that killed the process, or its exit status."""
    if os.WIFSIGNALED(status):
        from stiefelsym.run.pool import ABORT_HINT, signal_name
        sig = os.WTERMSIG(status)
        hint = ABORT_HINT if sig == signal.SIGABRT else ""
        return f"killed by {signal_name(sig)}{hint}"
    if os.WIFEXITED(status):
        return f"exit status {os.WEXITSTATUS(status)}"
    return f"wait status {status}"


def next_chunk(rfd: int, deadline: float) -> bytes | None:
    """The next bytes a child wrote to ``rfd`` (b"" once every writer has closed it), or None when the
    ``deadline`` (of :func:`time.monotonic`) passes first.  The one way the engine waits on a child's pipe
    (:func:`read_pipe`, and the claims file's tracer reading its children's lines)."""
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            return None
        ready, _, _ = select.select([rfd], [], [], left)
        if ready:
            return os.read(rfd, 1 << 16)


def read_pipe(rfd: int, seconds: float, on_fail: Callable[[], None]) -> bytes | None:
    """Everything a child writes to ``rfd`` until it closes it, or None once ``seconds`` have passed;
    ``rfd`` is closed, and ``on_fail()`` (which kills the child) is called on a timeout or when the
    wait is interrupted."""
    chunks: list[bytes] = []
    deadline = time.monotonic() + seconds
    try:
        while True:
            chunk = next_chunk(rfd, deadline)
            if chunk is None:
                on_fail()
                return None
            if not chunk:
                break
            chunks.append(chunk)
    except BaseException:
        on_fail()
        raise
    finally:
        os.close(rfd)
    return b"".join(chunks)


def _kill(pid: int) -> None:
    try:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
    except (ProcessLookupError, ChildProcessError):
        pass
