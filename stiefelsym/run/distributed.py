"""The verification plan on a dask.distributed cluster (``verify --scheduler ADDRESS``).

The runs (claim, size, method) of a plan are independent.  Here each one is a dask
task; on the dask worker it executes exactly as a local run does, in a forked process
of :class:`stiefelsym.run.pool.WorkerPool` with the same wall-time and memory budgets, and
what comes back is the pool's raw :class:`~stiefelsym.run.pool.Outcome`.

A dask worker is a multi-threaded process (its event loop, its task threads: a default
``dask worker`` runs two), and a fork from it may copy a lock another thread holds (an
import, the allocator), so the child stalls until its budget runs out.  So the worker
never forks: each of its task threads hands the run to a *run server*, a fresh
single-threaded Python process (:func:`serve`, started with exec,
which loads the catalog once and keeps a budgeted :class:`~stiefelsym.run.pool.WorkerPool`),
over a pipe.  Threaded workers are therefore fine (``--nthreads 1`` is not needed); the
run servers of a worker are started ahead by the :class:`StiefelsymPlugin` registered
on the cluster, which also reports the worker's stiefelsym version (a worker with
another version is refused: exit 2).

The client waits with a deadline: when no worker is left for :data:`NO_WORKER_SECONDS`,
when no run completes for the run budget plus :data:`STALL_SECONDS`, or when dask gives
up on a run (its worker died again and again), the command stops with exit 2 and says
why; a worker lost mid-run is replaced by dask and its runs are computed again, with
the same verdicts.  The verdict policy
(which verdicts the catalog expects, erratum sizes, rerun commands) is applied here, in
the client, by the runner's own code, in the order of the plan: the results, their order
and their verdicts are those of a serial run.  The corrections of a claim whose printed
statement fails are run afterwards, as the runner does.  Reports are written once, by the
client (the command line).

Claims reach the workers by name: a catalog claim as its id (the worker loads the
catalog, which must be installed there), a claim of a user's file as the file's text
(the run server loads it from a private copy as the command line does, imported and traced in
child processes at the run's size: nothing of a user's file runs in the run server, which
computes and sends back the outcomes of every file's runs).  dask is imported only here, and only when a
scheduler is given (``pip install 'stiefelsym[dask]'``).
"""
from __future__ import annotations

import hashlib
import inspect
import os
import pickle
import struct
import subprocess
import sys
import tempfile
import threading
import time
import uuid
from pathlib import Path
from typing import Any, Callable, Iterable

from stiefelsym.claims import CATALOG, Claim, Size
from stiefelsym.run.pool import DEFAULT_MEMORY_GIB, DEFAULT_TIMEOUT, GIB, Outcome, _read_exactly
from stiefelsym.results import Result

#: seconds to wait for the scheduler when connecting
CONNECT_TIMEOUT = 30.0
#: seconds the client waits with no worker in the cluster before it gives up (exit 2)
NO_WORKER_SECONDS = 60.0
#: seconds beyond the run budget the client waits for some run to complete before it gives up
STALL_SECONDS = 300.0
#: seconds beyond the run budget a task thread waits for its run server's answer
SERVER_GRACE = 120.0
#: how often the client looks at the cluster while it waits (seconds)
POLL_SECONDS = 1.0


class DistributedError(ValueError):
    """The cluster cannot be used (dask missing, scheduler unreachable): bad input, exit 2."""


def _claim_origin(claim: Claim) -> tuple[str, str]:
    """("catalog", module) for a claim of the installed catalog, ("file", text) for a user's file."""
    module = claim.source or getattr(claim.func, "__module__", "") or ""
    if claim.reviewed and (module == CATALOG or module.startswith(CATALOG + ".")):
        return ("catalog", module)
    try:
        # a claim of a file loaded in child processes (the command line's --claims): the file this process loaded
        path = getattr(claim.func, "loaded_from", None) or inspect.getsourcefile(claim.func)
        text = Path(path).read_text(encoding="utf-8") if path else None
    except (OSError, TypeError):
        text = None
    if text is None:
        raise DistributedError(f"claim {claim.id}: its source file cannot be read, so it cannot be sent "
                               "to the cluster's workers")
    return ("file", text)


# --------------------------------------------------------------------------- the worker's side

_REGISTRIES: dict[tuple, Any] = {}
_REGISTRIES_LOCK = threading.Lock()


def _registry(origin: tuple[str, str], size: tuple[int, int] | None = None, claim: str | None = None) -> Any:
    """The registry holding a claim, loaded once per process (under a lock: a registry is cached
    only once it is completely loaded).  A user's file is loaded as the command line loads it: imported and
    traced in child processes (:func:`stiefelsym.run.userfile.load_claims_isolated`), at the run's size, so that
    nothing of it runs in this process, which computes and sends back the outcomes of every file's runs."""
    digest = "" if origin[0] == "catalog" else hashlib.sha256(origin[1].encode()).hexdigest()
    key = ("catalog", "") if origin[0] == "catalog" else ("file", digest, size, claim)
    with _REGISTRIES_LOCK:
        reg = _REGISTRIES.get(key)
        if reg is not None:
            return reg
        from stiefelsym.claims import load_catalog
        from stiefelsym.run.userfile import load_claims_isolated
        if origin[0] == "catalog":
            reg = load_catalog()
        else:
            d = Path(tempfile.gettempdir()) / f"stiefelsym-dask-{os.getuid() if hasattr(os, 'getuid') else 0}"
            d.mkdir(parents=True, exist_ok=True)
            path = d / f"claims_{digest[:16]}.py"
            if not path.is_file():
                tmp = path.with_suffix(f".{os.getpid()}.{threading.get_ident()}.tmp")
                tmp.write_text(origin[1], encoding="utf-8")
                os.replace(tmp, path)
            reg = load_claims_isolated(path, [size] if size is not None else (),
                                       only=None if claim is None else [claim])
        _REGISTRIES[key] = reg
        return reg


def run_here(spec: dict[str, Any]) -> Outcome:
    """One run in this (single-threaded) process's budgeted forked worker: the pool's raw outcome."""
    from stiefelsym.run import runner
    from stiefelsym._version import __version__
    from stiefelsym.run.pool import WorkerPool
    from stiefelsym.methods.fixed_size import _describe
    if spec.get("version", __version__) != __version__:
        return Outcome("error", message=f"this worker has stiefelsym {__version__}, the client "
                                        f"{spec['version']}")
    size = None if spec["n"] is None else (spec["n"], spec["r"])
    claim = _registry(tuple(spec["origin"]), size, spec["claim"]).get(spec["claim"])
    claims = [claim]
    task = (0, spec["n"], spec["r"], spec["method"], spec["correction"])
    runner._preload([task], long_run=True)
    memory = None if spec["memory"] is None else int(spec["memory"] * GIB)
    timeout = spec["timeout"]
    pool: WorkerPool

    def execute(t: tuple) -> Result:
        return runner._execute(claims, spec["seed"], spec["hard"], timeout, pool.forking, t)

    with WorkerPool(execute, workers=1, timeout=timeout, memory=memory, describe=_describe) as pool:
        for _, outcome in pool.run([task]):
            return outcome
    return Outcome("error", message="the run produced no outcome")


# --------------------------------------------------------------------------- run servers

_FRAME = struct.Struct(">Q")


def _write_frame(stream: Any, obj: Any) -> None:
    data = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    stream.write(_FRAME.pack(len(data)) + data)
    stream.flush()


def _read_frame(fd: int, deadline: float | None = None) -> Any:
    head = _read_exactly(fd, _FRAME.size, deadline)
    if head is None:
        return None
    body = _read_exactly(fd, _FRAME.unpack(head)[0], deadline)
    return None if body is None else pickle.loads(body)


def serve() -> None:
    """The run server's loop: read a spec, answer with the
    run's outcome, until standard input closes.  Standard output carries only the answers (what
    anything else prints goes to standard error)."""
    out = os.fdopen(os.dup(1), "wb")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    from stiefelsym.run import runner
    _registry(("catalog", ""))                 # ready before the first run
    runner._preload([(0, 1, 1, "auto", -1)], long_run=True)
    _write_frame(out, ("ready", None))
    while True:
        spec = _read_frame(sys.stdin.fileno())
        if spec is None:
            return
        try:
            reply: Any = run_here(spec)
        except Exception as exc:  # noqa: BLE001 - the claim's file did not load, say: the run's error
            reply = Outcome("error", message=f"{type(exc).__name__}: {exc}")
        try:
            _write_frame(out, reply)
        except OSError:                        # the dask worker is gone: so is this server
            return


class _Server:
    """A run server process, seen from a dask worker's task thread."""

    def __init__(self) -> None:
        # exec'd, not forked: PYTHONSAFEPATH keeps the worker's current directory off its path
        env = dict(os.environ, PYTHONSAFEPATH="1")
        self.proc = subprocess.Popen([sys.executable, "-c", "from stiefelsym.run.distributed import serve; serve()"],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, close_fds=True, env=env)
        self.ready = False

    def alive(self) -> bool:
        return self.proc.poll() is None

    def call(self, spec: dict[str, Any], seconds: float) -> Outcome:
        deadline = time.monotonic() + seconds
        assert self.proc.stdin is not None and self.proc.stdout is not None
        if not self.ready:
            if _read_frame(self.proc.stdout.fileno(), deadline) is None:
                raise EOFError
            self.ready = True
        _write_frame(self.proc.stdin, spec)
        reply = _read_frame(self.proc.stdout.fileno(), deadline)
        if reply is None:
            raise EOFError
        return reply

    def kill(self) -> None:
        try:
            self.proc.kill()
            self.proc.wait()
        except OSError:
            pass


_IDLE: list[_Server] = []
_IDLE_LOCK = threading.Lock()


def _take_server() -> _Server:
    with _IDLE_LOCK:
        while _IDLE:
            server = _IDLE.pop()
            if server.alive():
                return server
    return _Server()


def start_servers(count: int) -> None:
    """Start ``count`` run servers ahead (the plugin does, one per task thread of the worker)."""
    with _IDLE_LOCK:
        missing = count - sum(1 for s in _IDLE if s.alive())
    for _ in range(max(missing, 0)):
        server = _Server()
        with _IDLE_LOCK:
            _IDLE.append(server)


def stop_servers() -> None:
    """Stop this worker's idle run servers."""
    with _IDLE_LOCK:
        servers = list(_IDLE)
        _IDLE.clear()
    for server in servers:
        server.kill()


def run_remote(spec: dict[str, Any]) -> Outcome:
    """One run on a dask worker: handed to an idle run server of this worker (started if there is
    none), never forked from the worker's own multi-threaded process."""
    server = _take_server()
    try:
        outcome = server.call(spec, spec["timeout"] + SERVER_GRACE)
    except (TimeoutError, EOFError, OSError, pickle.UnpicklingError) as exc:
        server.kill()
        what = "did not answer in time" if isinstance(exc, TimeoutError) else "died"
        return Outcome("died", message=f"the run server of the dask worker {what} "
                                       f"(budget {spec['timeout']:g} s)")
    with _IDLE_LOCK:
        _IDLE.append(server)
    return outcome


def worker_version() -> str:
    """The stiefelsym version of the process it runs in (a dask worker, asked by the client)."""
    from stiefelsym._version import __version__
    return __version__


def plugin() -> Any:
    """The worker plugin to register on a cluster (``client.register_plugin(plugin())``)."""
    from stiefelsym.run._dask_plugin import StiefelsymPlugin
    return StiefelsymPlugin(start_servers, stop_servers)


# --------------------------------------------------------------------------- the client's side

def _client(address: str) -> Any:
    try:
        from distributed import Client
    except ImportError as exc:
        raise DistributedError("--scheduler needs dask.distributed: pip install 'stiefelsym[dask]' "
                               f"({exc})") from None
    try:
        return Client(address, timeout=CONNECT_TIMEOUT, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise DistributedError(f"cannot connect to the dask scheduler at {address}: {exc}") from None


def verify(claims: list[Claim], *, address: str | None = None, client: Any = None,
           sizes: list[Size] | None = None, methods: Iterable[str] = ("auto",), seed: int = 0,
           on_result: Callable[[Result], None] | None = None, on_plan: Callable[[int], None] | None = None,
           hard: str | None = None, timeout: float = DEFAULT_TIMEOUT,
           memory: float | None = DEFAULT_MEMORY_GIB, jobs: int = 1, strict_sizes: bool = False,
           fork: bool | None = None, **plan_options: Any) -> list[Result]:
    """``runner.verify`` on a dask cluster (``address``, or an existing ``client``): the same
    arguments (``jobs`` and ``fork`` are the cluster's business and are ignored; other keyword
    arguments go to ``runner.plan``), the same results in the same order."""
    from stiefelsym.run import runner
    methods = runner.checked_options(seed, timeout, memory, hard, methods)
    claims = list(claims)
    # further options of the runner's plan (e.g. a cost budget) are passed on as they are
    runs = runner.plan(claims, sizes, methods, strict=strict_sizes, **plan_options)
    if on_plan is not None:
        on_plan(len(runs))
    index = {id(c): i for i, c in enumerate(claims)}
    tasks = [(index[id(c)], None if s is None else s.n, None if s is None else s.r, m, -1) for c, s, m in runs]
    results: list[Result] = []
    if not tasks:
        return results
    origins = {i: _claim_origin(c) for i, c in enumerate(claims)}
    own = client is None
    if own:
        if address is None:
            raise DistributedError("no dask scheduler given")
        client = _client(address)
    from stiefelsym._version import __version__
    try:
        _prepare(client, __version__)
    except BaseException:
        if own:
            client.close()
        raise

    def spec(task: tuple) -> dict[str, Any]:
        ci, n, r, m, k = task
        return {"origin": origins[ci], "claim": claims[ci].id, "n": n, "r": r, "method": m, "correction": k,
                "seed": seed, "hard": hard, "timeout": float(timeout), "memory": memory, "version": __version__}

    def deliver(res: Result) -> None:
        results.append(res)
        if on_result is not None:
            on_result(res)

    def run(batch: list[tuple]) -> Iterable[tuple[int, Outcome]]:
        # pure=False: a run is never deduplicated or cached by the scheduler
        futures = [client.submit(run_remote, spec(t), pure=False, key=f"stiefelsym-run-{uuid.uuid4().hex}")
                   for i, t in enumerate(batch)]
        watch = _Watch(client, float(timeout))
        try:
            for i, fut in enumerate(futures):
                watch.wait(fut)
                try:
                    outcome = fut.result()
                except Exception as exc:  # noqa: BLE001 - dask gave up on the run (its workers died)
                    raise DistributedError(f"the cluster did not complete a run ({claims[batch[i][0]].id}): "
                                           f"{type(exc).__name__}: {exc}") from None
                if not isinstance(outcome, Outcome):
                    raise DistributedError("the cluster returned something else than a run's outcome")
                yield i, outcome
        finally:
            client.cancel([f for f in futures if not f.done()])

    try:
        runner.run_with_corrections(run, tasks, claims, seed, hard, deliver)
    finally:
        if own:
            client.close()
    return results


def _prepare(client: Any, version: str) -> None:
    """Register the plugin (it starts the workers' run servers) and check the workers' versions."""
    register = getattr(client, "register_plugin", None) or client.register_worker_plugin
    try:
        register(plugin(), name="stiefelsym")
        versions = client.run(worker_version)
    except Exception as exc:  # noqa: BLE001 - a worker without stiefelsym, say
        raise DistributedError(f"the dask workers cannot run stiefelsym: {type(exc).__name__}: {exc} "
                               "(install the same stiefelsym on every worker)") from None
    other = {addr: v for addr, v in versions.items() if v != version}
    if other:
        addr, v = next(iter(other.items()))
        raise DistributedError(f"{len(other)} dask worker(s) run stiefelsym {v} (e.g. {addr}), this client "
                               f"{version}: install the same version everywhere")


class _Watch:
    """The client's deadline while it waits for a run: no worker left for NO_WORKER_SECONDS, or no
    run completed for the run budget plus STALL_SECONDS, is an error (exit 2), never a hang."""

    def __init__(self, client: Any, timeout: float) -> None:
        self.client = client
        self.stall = timeout + STALL_SECONDS
        self.progress = time.monotonic()
        self.no_worker_since: float | None = None

    def wait(self, fut: Any) -> None:
        while True:
            try:
                # the future's own wait (distributed.wait would need a default client: this one is not)
                fut.result(timeout=POLL_SECONDS)
            except Exception:  # noqa: BLE001 - not done yet, or failed: the caller reads fut.result() again
                pass
            if fut.done():
                self.progress = time.monotonic()
                return
            now = time.monotonic()
            try:
                workers = self.client.scheduler_info(n_workers=-1).get("workers", {})
            except TypeError:            # older distributed: no n_workers argument
                workers = self.client.scheduler_info().get("workers", {})
            except Exception as exc:  # noqa: BLE001 - the scheduler is gone
                raise DistributedError(f"lost the dask scheduler: {type(exc).__name__}: {exc}") from None
            if workers:
                self.no_worker_since = None
            elif self.no_worker_since is None:
                self.no_worker_since = now
            elif now - self.no_worker_since >= NO_WORKER_SECONDS:
                raise DistributedError(f"no dask worker is left in the cluster (none for {NO_WORKER_SECONDS:g} s); "
                                       "start workers (dask worker ADDRESS) and run again")
            if now - self.progress >= self.stall:
                raise DistributedError(f"the cluster completed no run for {self.stall:g} s (the run budget "
                                       f"plus {STALL_SECONDS:g} s): its workers are stuck or overloaded")


def verifier(address: str) -> Callable[..., list[Result]]:
    """A function with the signature of ``runner.verify`` that runs the plan on the cluster at
    ``address`` (used by ``stiefelsym verify --scheduler ADDRESS``)."""
    def run(claims: list[Claim], **kw: Any) -> list[Result]:
        return verify(claims, address=address, **kw)
    return run
