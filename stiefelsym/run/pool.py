"""A small pool of forked worker processes with hard budgets.

Every verification run executes in a worker: a child forked from the process
that built the plan (so it has every claim loaded), which receives job numbers
over a pipe and sends back pickled results.  Each job has a wall-time budget,
enforced from the parent (the worker is killed with SIGKILL, whatever it is
doing: looping, sleeping with signals blocked, stuck in native code), and the
worker has a memory budget (``RLIMIT_AS``, soft and hard).  A worker that dies
(out of memory, a segfault, ``os._exit``) or is killed is replaced by a fresh
one; the job gets an outcome that says so.

In a worker, standard output (``sys.stdout`` and file descriptor 1) goes to
standard error and standard input reads from /dev/null, so nothing a claim
prints can reach the parent's standard output.  Workers are in their own
process group (killed together with anything they started), ignore SIGINT (the
parent handles Ctrl-C) and, on Linux, die with the parent.

Where ``os.fork`` is not available the jobs run in-process, without budgets.
"""
from __future__ import annotations

import gc
import os
import pickle
import select
import signal
import struct
import sys
import time
from collections import deque
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Sequence

GIB = 1 << 30
#: the default budgets of one job: wall time (seconds) and address space (GiB)
DEFAULT_TIMEOUT = 300.0
DEFAULT_MEMORY_GIB = 4.0
#: the largest time budget (seconds, about 31 years) and memory budget (GiB) a run takes
MOST_SECONDS, MOST_GIB = 1e9, 1e6
#: the amounts a run takes (the command line's options, :func:`stiefelsym.verify`'s arguments): unit, largest
AMOUNTS = {"timeout": ("seconds", MOST_SECONDS), "memory": ("GiB", MOST_GIB), "budget": ("seconds", MOST_SECONDS)}


def amount_problem(name: str, x: object) -> str:
    """Why ``x`` is not an amount ``name`` of :data:`AMOUNTS` ("" when it is one): a positive int or float up to
    its largest.  nan fails every comparison and inf exceeds the largest, so both are refused (nan would switch
    a time limit off; inf reached select() and int())."""
    import numbers
    unit, most = AMOUNTS[name]
    if not isinstance(x, numbers.Real) or isinstance(x, bool) or not (0 < x <= most):   # numpy's numbers too
        return f"the {name} must be a positive number of {unit}, at most {most:g}, not {x!r}"
    return ""
#: a worker retires after a job once its resident memory has grown by more than this (bytes) since it
#: started, and a fresh one, forked from the parent, takes the next job: every symbolic attempt at
#: n >= 6 runs in a child forked from the worker, and a fork (with the child's exit) costs system time
#: in proportion to the memory mapped (measured: about 70 ms per GiB, parent and child together,
#: against workers that grew to 0.8-1.2 GiB over a run of the catalog at n <= 7)
RECYCLE_GROWTH = 384 << 20
_HEADER = struct.Struct(">Q")


class Terminated(BaseException):
    """The process received SIGTERM (raised by :func:`raise_on_sigterm`)."""


@dataclass
class Outcome:
    """What happened to one job: ``ok`` (value is the job's return value), ``timeout``,
    ``died`` or ``memory`` (the job exhausted its memory budget), ``error`` (the job raised;
    value is the description).  ``message`` explains anything but ``ok``."""

    kind: str
    value: Any = None
    message: str = ""
    seconds: float = 0.0


def fork_available() -> bool:
    return hasattr(os, "fork") and hasattr(os, "setpgid")


def format_seconds(seconds: float) -> str:
    return f"{seconds:g}"


def format_gib(nbytes: int | None) -> str:
    return "no limit" if nbytes is None else f"{nbytes / GIB:g} GiB"


# --------------------------------------------------------------------------- stdout

def _redirect_fd1() -> int | None:
    """Point file descriptor 1 at standard error (or /dev/null); the saved descriptor."""
    try:
        saved = os.dup(1)
    except OSError:
        saved = None
    try:
        os.dup2(2, 1)
    except OSError:
        try:
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, 1)
            os.close(null)
        except OSError:
            pass
    return saved


@contextmanager
def stdout_to_stderr() -> Iterator[None]:
    """Meanwhile, whatever is written to standard output (``print``, ``sys.stdout``,
    file descriptor 1) goes to standard error."""
    old = sys.stdout
    for stream in (old, sys.__stdout__):
        try:
            if stream is not None:
                stream.flush()
        except (OSError, ValueError, AttributeError):
            pass
    saved = _redirect_fd1()
    sys.stdout = sys.stderr
    try:
        yield
    finally:
        try:
            sys.stdout.flush()
        except (OSError, ValueError, AttributeError):
            pass
        sys.stdout = old
        if saved is not None:
            try:
                os.dup2(saved, 1)
            finally:
                os.close(saved)


# --------------------------------------------------------------------------- SIGTERM

def _raise_terminated(signum: int, frame: Any) -> None:
    raise Terminated()


@contextmanager
def raise_on_sigterm() -> Iterator[None]:
    """Meanwhile SIGTERM raises :class:`Terminated` (so that ``finally`` clauses, which
    kill the workers, run).  Does nothing outside the main thread."""
    try:
        old = signal.signal(signal.SIGTERM, _raise_terminated)
    except (ValueError, AttributeError, OSError):   # not the main thread, or no SIGTERM
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, old)


# --------------------------------------------------------------------------- framing

def write_fully(fd: int, data: bytes) -> None:
    """All of ``data`` to ``fd`` (os.write may write part of it to a pipe)."""
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]


def _send(fd: int, obj: Any) -> None:
    data = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    write_fully(fd, _HEADER.pack(len(data)) + data)


def _read_exactly(fd: int, n: int, deadline: float | None = None) -> bytes | None:
    """n bytes from fd (None at end of file); TimeoutError past ``deadline`` (time.monotonic())."""
    chunks, left = [], n
    while left:
        if deadline is not None:
            wait = deadline - time.monotonic()
            if wait <= 0 or not select.select([fd], [], [], wait)[0]:
                raise TimeoutError
        chunk = os.read(fd, min(left, 1 << 20))
        if not chunk:
            return None
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def _receive(fd: int) -> Any:
    head = _read_exactly(fd, _HEADER.size)
    if head is None:
        return None
    body = _read_exactly(fd, _HEADER.unpack(head)[0])
    return None if body is None else pickle.loads(body)


# --------------------------------------------------------------------------- the worker

_prctl: Any = None


def _death_signal_setup() -> Any:
    """prctl(PR_SET_PDEATHSIG) on Linux, looked up once in the parent."""
    global _prctl
    if _prctl is None and sys.platform.startswith("linux"):
        try:
            import ctypes
            _prctl = ctypes.CDLL(None, use_errno=True).prctl
        except (OSError, AttributeError, ImportError):
            _prctl = False
    return _prctl


def resident_bytes() -> int:
    """The resident memory of this process (bytes), 0 where /proc does not say."""
    try:
        with open("/proc/self/statm", "rb") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


def _worker_main(task_fd: int, result_fd: int, execute: Callable[[Any], Any],
                 memory: int | None, describe: Callable[[BaseException], str], mask: Any,
                 recycle: int | None = None) -> None:
    """The worker's life: set up, then run jobs until the task pipe closes, or until its resident
    memory has grown by more than ``recycle`` bytes (it retires after that job).  Never returns."""
    try:
        code = 0
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        if mask is not None:
            signal.pthread_sigmask(signal.SIG_SETMASK, mask)
        try:
            os.setpgid(0, 0)
        except OSError:
            pass
        if hasattr(signal, "SIGTTOU"):
            signal.signal(signal.SIGTTOU, signal.SIG_IGN)   # may write to the terminal from its own group
        if _prctl:
            _prctl(1, signal.SIGKILL)                         # PR_SET_PDEATHSIG: die with the parent
            if os.getppid() == 1:
                os._exit(0)
        keep = sorted({task_fd, result_fd})
        lo = 3
        for fd in keep:                                       # nothing else of the parent's: no way to its stdout
            os.closerange(lo, fd)
            lo = fd + 1
        os.closerange(lo, _max_fd())
        try:
            null = os.open(os.devnull, os.O_RDONLY)
            os.dup2(null, 0)
            os.close(null)
        except OSError:
            pass
        _redirect_fd1()
        sys.stdout = sys.stderr
        from stiefelsym.backends.blas import tune_worker_process
        tune_worker_process()
        if memory is not None:
            import resource
            # the native libraries are mapped before the budget applies: it bounds what a run computes, and a
            # small budget would otherwise fail the first run that loads one as an ImportError ("failed to map
            # segment"), not as the memory budget it is
            for name in ("flint", "symengine"):
                try:
                    __import__(name)
                except ImportError:
                    pass
            soft, hard = resource.getrlimit(resource.RLIMIT_AS)
            # the budget is the run's: what the worker has mapped already (the interpreter, the libraries, and in
            # a process that forks from a long-lived one, such as a test session, all it holds) comes on top
            wanted = memory + _mapped_bytes()
            limit = wanted if hard == resource.RLIM_INFINITY else min(wanted, hard)
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        limit = None if recycle is None else resident_bytes() + recycle
        while True:
            msg = _receive(task_fd)
            if msg is None:
                break
            index, task = msg
            retire = False
            try:
                reply: tuple = ("ok", execute(task))
            except MemoryError as exc:
                reply, retire = ("memory", describe(exc)), True
            except BaseException as exc:  # noqa: BLE001 - SystemExit, KeyboardInterrupt, anything
                reply = ("error", describe(exc))
            if limit is not None and not retire and resident_bytes() > limit:
                retire = True
            try:
                _send(result_fd, (index, reply, retire))
            except MemoryError:
                code = 3
                break
            except BaseException as exc:  # noqa: BLE001 - an unpicklable result, say
                _send(result_fd, (index, ("error", f"the result could not be sent back: {describe(exc)}"), True))
                break
            if retire:
                break
    except BaseException:  # noqa: BLE001 - never unwind into the parent's code
        code = 2
    finally:
        os._exit(code)


def _mapped_bytes() -> int:
    """The address space this process has mapped (Linux: /proc/self/statm; 0 where it cannot be read)."""
    try:
        with open("/proc/self/statm", encoding="ascii") as f:
            return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError, AttributeError):
        return 0


def _max_fd() -> int:
    try:
        return max(int(os.sysconf("SC_OPEN_MAX")), 1 << 16)
    except (ValueError, OSError, AttributeError):
        return 1 << 16


_SIGNALS = {signal.SIGINT, signal.SIGTERM}


class _Worker:
    def __init__(self, pid: int, task_fd: int, result_fd: int) -> None:
        self.pid, self.task_fd, self.result_fd = pid, task_fd, result_fd
        self.job: int | None = None
        #: the affinity key of the last task it was given (see :meth:`WorkerPool.run`)
        self.key: Any = None
        #: which process of the pool it is (1 for the first forked, and so on)
        self.number = 0
        self.started = 0.0
        self.deadline = 0.0
        self.buffer = bytearray()


def signal_name(sig: int) -> str:
    """A signal's name (SIGKILL), or its number."""
    try:
        return signal.Signals(sig).name
    except ValueError:
        return f"signal {sig}"


#: said of a process killed by SIGABRT: flint aborts the process when an allocation fails
ABORT_HINT = "; a native library aborted, as flint does when an allocation fails under the memory budget"


def _died(status: int) -> str:
    if os.WIFSIGNALED(status):
        sig = os.WTERMSIG(status)
        return f"killed by {signal_name(sig)}{ABORT_HINT if sig == signal.SIGABRT else ''}"
    if os.WIFEXITED(status):
        return f"the worker process exited with status {os.WEXITSTATUS(status)}"
    return f"wait status {status}"


class WorkerPool:
    """Run jobs ``execute(task)`` in up to ``workers`` forked processes.

    ``execute`` and everything it needs must exist before the first job is
    submitted (workers are forked then, and again after a worker is lost).
    Tasks and return values cross a pipe, pickled.  A worker whose resident memory has grown by more
    than ``recycle`` bytes retires after its job (None: never).  Use as a context manager:
    leaving it kills every worker."""

    def __init__(self, execute: Callable[[Any], Any], *, workers: int = 1, timeout: float = 300.0,
                 memory: int | None = 4 * GIB, describe: Callable[[BaseException], str] | None = None,
                 fork: bool | None = None, recycle: int | None = RECYCLE_GROWTH) -> None:
        if workers < 1:
            raise ValueError("a pool needs at least one worker")
        if timeout <= 0:
            raise ValueError("the time budget must be positive")
        self.execute = execute
        self.size = workers
        self.timeout = float(timeout)
        self.memory = memory
        self.recycle = recycle
        self.describe = describe or (lambda exc: f"{type(exc).__name__}: {exc}")
        self.forking = fork_available() if fork is None else fork and fork_available()
        self.workers: list[_Worker] = []
        self.spawned = 0        # the worker processes forked so far
        if self.forking:
            _death_signal_setup()

    # -- workers

    def _spawn(self) -> _Worker:
        task_r, task_w = os.pipe()
        result_r, result_w = os.pipe()
        for fd in (task_w, result_r):
            os.set_inheritable(fd, False)
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError, AttributeError):
                pass
        # SIGINT and SIGTERM wait until both processes are set up (the child resets their handlers,
        # the parent has registered the worker, so that it is killed with the others)
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, _SIGNALS) if hasattr(signal, "pthread_sigmask") \
            else None
        try:
            gc.freeze()    # the inherited objects stay out of the worker's collections (fewer copied pages)
            try:
                pid = os.fork()
                if pid == 0:
                    _worker_main(task_r, result_w, self.execute, self.memory, self.describe, mask,
                                 self.recycle)
            except BaseException:
                for fd in (task_r, task_w, result_r, result_w):
                    os.close(fd)
                raise
            finally:
                gc.unfreeze()
            os.close(task_r)
            os.close(result_w)
            try:
                os.setpgid(pid, pid)
            except OSError:
                pass
            w = _Worker(pid, task_w, result_r)
            self.spawned += 1
            w.number = self.spawned
            self.workers.append(w)
        finally:
            if mask is not None:
                signal.pthread_sigmask(signal.SIG_SETMASK, mask)
        return w

    def _reap(self, w: _Worker, kill: bool) -> int | None:
        """Remove a worker (killing it and its process group first if asked); its wait status."""
        if kill:
            for killer in (os.killpg, os.kill):
                try:
                    killer(w.pid, signal.SIGKILL)
                except OSError:
                    pass
        if w in self.workers:
            self.workers.remove(w)
        for fd in (w.task_fd, w.result_fd):
            try:
                os.close(fd)
            except OSError:
                pass
        while True:
            try:
                return os.waitpid(w.pid, 0)[1]
            except ChildProcessError:
                return None
            except InterruptedError:
                continue

    def close(self) -> None:
        """Stop every worker (killed with its process group, then reaped)."""
        for w in list(self.workers):
            self._reap(w, kill=True)

    def __enter__(self) -> "WorkerPool":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    # -- jobs

    def run(self, tasks: Sequence[Any] | Iterator[Any],
            affinity: Callable[[Any], Any] | None = None, prepare: Callable[[Any, int], Any] | None = None,
            on_outcome: Callable[[Any, Outcome, int], None] | None = None) -> Iterator[tuple[int, Outcome]]:
        """Outcomes of the tasks, in the order of ``tasks`` (computed up to ``workers`` at once).  An
        iterator of tasks is drawn from only when a worker is free for its next task (what makes a task,
        such as the plan's look at which runs are one computation, is done while the workers compute).

        ``affinity`` (a key of a task, such as the claim it runs): a free worker takes the next task of the key
        of its last task, else the next task of a key no other worker has, drawing ahead for one (the tasks
        passed over wait for their worker); only when there is none does it take another worker's next task.
        So the tasks of one key run in one worker, in order, while there is other work, and what a worker
        computed for one task serves the next of its key.  The outcomes come in the order of ``tasks``
        whatever the workers did.

        ``prepare(task, worker)`` (in this process): what ``execute`` is given for a task, made when the task is
        handed to its worker (not when it is drawn), so that it can carry what the jobs ended by then computed;
        ``worker`` numbers the worker process (each process forked for the pool has its own number; 0 where the
        jobs run in this process);
        ``on_outcome(task, outcome, worker)`` (in this process) sees each task with its outcome and the number of
        its worker as soon as its job has ended, whatever the order of ``tasks``."""
        if not self.forking:
            for i, task in enumerate(tasks):
                t0 = time.perf_counter()
                try:
                    value = self.execute(task if prepare is None else prepare(task, 0))
                except (KeyboardInterrupt, Terminated):
                    raise
                except MemoryError as exc:
                    outcome = Outcome("memory", message=self.describe(exc), seconds=time.perf_counter() - t0)
                except BaseException as exc:  # noqa: BLE001
                    outcome = Outcome("error", message=self.describe(exc), seconds=time.perf_counter() - t0)
                else:
                    outcome = Outcome("ok", value, seconds=time.perf_counter() - t0)
                if on_outcome is not None:
                    on_outcome(task, outcome, 0)
                yield i, outcome
            return
        source = iter(tasks)
        drawn: list[Any] = []            # the tasks drawn so far, by index
        more = True                      # the source may have more
        pending: deque[int] = deque()    # drawn, not yet sent (or sent to a worker that was lost)

        def draw() -> bool:
            nonlocal more
            if more:
                try:
                    drawn.append(next(source))
                except StopIteration:
                    more = False
                else:
                    pending.append(len(drawn) - 1)
            return bool(pending)

        done: dict[int, Outcome] = {}
        following = 0
        try:
            while more or following < len(drawn):
                while True:
                    idle = next((w for w in self.workers if w.job is None), None)
                    if idle is None and len(self.workers) >= self.size:
                        break
                    if not (pending or draw()):     # a task is drawn only for a free worker
                        break
                    if idle is None:
                        idle = self._spawn()
                    i = pending.popleft() if affinity is None else self._choose(idle, pending, drawn, draw, affinity)
                    idle.job, idle.buffer = i, bytearray()
                    idle.started = time.monotonic()
                    idle.deadline = idle.started + self.timeout
                    try:
                        _send(idle.task_fd, (i, drawn[i] if prepare is None else prepare(drawn[i], idle.number)))
                    except OSError:          # the worker is gone: a fresh one takes the job
                        pending.appendleft(i)
                        self._reap(idle, kill=True)
                busy = [w for w in self.workers if w.job is not None]
                if busy:
                    wait = max(0.0, min(w.deadline for w in busy) - time.monotonic())
                    try:
                        ready, _, _ = select.select([w.result_fd for w in busy], [], [], wait)
                    except InterruptedError:
                        ready = []
                    jobs = {w: w.job for w in busy}
                    for w in busy:
                        if w.result_fd in ready:
                            self._collect(w, done)
                    now = time.monotonic()
                    for w in busy:
                        if w.job is not None and w in self.workers and now >= w.deadline:
                            done[w.job] = Outcome("timeout", message=f"exceeded its time budget of "
                                                  f"{format_seconds(self.timeout)} s", seconds=now - w.started)
                            self._reap(w, kill=True)
                    if on_outcome is not None:
                        for w, j in jobs.items():
                            if j in done:       # its job ended here (a busy worker's job is never done before)
                                on_outcome(drawn[j], done[j], w.number)
                while following in done:
                    yield following, done.pop(following)
                    following += 1
        except BaseException:
            self.close()
            raise

    def _choose(self, w: _Worker, pending: "deque[int]", drawn: list[Any], draw: Callable[[], bool],
                affinity: Callable[[Any], Any]) -> int:
        """The task (an index of ``drawn``, taken out of ``pending``, which is not empty) for the free worker ``w``
        under ``affinity`` (see :meth:`run`)."""
        others = {v.key for v in self.workers if v is not w and v.key is not None}

        def fits(i: int, own: bool) -> bool:
            k = affinity(drawn[i])
            return k == w.key if own else k not in others
        pick = next((i for own in ((True, False) if w.key is not None else (False,))
                     for i in pending if fits(i, own)), None)
        while pick is None:
            n = len(pending)
            if not draw() or len(pending) == n:
                break
            last = pending[-1]
            if fits(last, True) or fits(last, False):
                pick = last
        if pick is None:
            pick = pending[0]        # every task left is another worker's: the first of them
        pending.remove(pick)
        w.key = affinity(drawn[pick])
        return pick

    def _collect(self, w: _Worker, done: dict[int, Outcome]) -> None:
        """Read what is available from a busy worker; on a whole message or on its death, finish the job."""
        try:
            chunk = os.read(w.result_fd, 1 << 20)
        except OSError:
            chunk = b""
        elapsed = time.monotonic() - w.started
        if chunk:
            w.buffer += chunk
            if len(w.buffer) < _HEADER.size:
                return
            size = _HEADER.unpack_from(w.buffer)[0]
            if len(w.buffer) < _HEADER.size + size:
                return
            try:
                index, (kind, value), retire = pickle.loads(bytes(w.buffer[_HEADER.size:_HEADER.size + size]))
            except Exception as exc:  # noqa: BLE001 - a garbled message
                done[w.job] = Outcome("error", message=f"the worker sent an unreadable result ({exc})",
                                      seconds=elapsed)
                self._reap(w, kill=True)
                return
            if index != w.job:
                done[w.job] = Outcome("error", message="the worker answered another job", seconds=elapsed)
                self._reap(w, kill=True)
                return
            if kind == "ok":
                done[index] = Outcome("ok", value, seconds=elapsed)
            elif kind == "memory":
                done[index] = Outcome("memory", message=f"exceeded its memory budget of "
                                      f"{format_gib(self.memory)} ({value})", seconds=elapsed)
            else:
                done[index] = Outcome("error", message=str(value), seconds=elapsed)
            w.job, w.buffer = None, bytearray()
            if retire:
                self._reap(w, kill=True)
            return
        status = self._reap(w, kill=True)          # end of file: the worker died
        how = _died(status) if status is not None else "the worker process vanished"
        done[w.job] = Outcome("died", message=(
            f"the computation died ({how}); its budget: {format_seconds(self.timeout)} s, "
            f"{format_gib(self.memory)} of memory"), seconds=elapsed)
