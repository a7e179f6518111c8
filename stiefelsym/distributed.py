"""The verification plan on a dask.distributed cluster (``verify --scheduler ADDRESS``).

The runs (claim, size, method) of a plan are independent.  Here each one is a dask
task; on the dask worker it executes exactly as a local run does, in a forked process
of :class:`stiefelsym.pool.WorkerPool` with the same wall-time and memory budgets, and
what comes back is the pool's raw :class:`~stiefelsym.pool.Outcome`.  The verdict policy
(which verdicts the catalog expects, erratum sizes, rerun commands) is applied here, in
the client, by the runner's own code, in the order of the plan: the results, their order
and their verdicts are those of a serial run.  The corrections of a claim whose printed
statement fails are run afterwards, as the runner does.  Reports are written once, by the
client (the command line).

Claims reach the workers by name: a catalog claim as its id (the worker loads the
catalog, which must be installed there), a claim of a user's file as the file's text
(the worker loads it from a private copy).  dask is imported only here, and only when a
scheduler is given (``pip install 'stiefelsym[dask]'``).
"""
from __future__ import annotations

import hashlib
import inspect
import os
import tempfile
import uuid
from pathlib import Path
from typing import Any, Callable, Iterable

from .claims import CATALOG, Claim, Size
from .pool import DEFAULT_MEMORY_GIB, DEFAULT_TIMEOUT, GIB, Outcome
from .results import Result

#: seconds to wait for the scheduler when connecting
CONNECT_TIMEOUT = 30.0


class DistributedError(ValueError):
    """The cluster cannot be used (dask missing, scheduler unreachable): bad input, exit 2."""


def _claim_origin(claim: Claim) -> tuple[str, str]:
    """("catalog", module) for a claim of the installed catalog, ("file", text) for a user's file."""
    module = claim.source or getattr(claim.func, "__module__", "") or ""
    if module == CATALOG or module.startswith(CATALOG + "."):
        return ("catalog", module)
    try:
        path = inspect.getsourcefile(claim.func)
        text = Path(path).read_text(encoding="utf-8") if path else None
    except (OSError, TypeError):
        text = None
    if text is None:
        raise DistributedError(f"claim {claim.id}: its source file cannot be read, so it cannot be sent "
                               "to the cluster's workers")
    return ("file", text)


# --------------------------------------------------------------------------- the worker's side

_REGISTRIES: dict[tuple[str, str], Any] = {}


def _registry(origin: tuple[str, str]) -> Any:
    """The registry holding a claim on this dask worker, loaded once per worker process."""
    key = ("catalog", "") if origin[0] == "catalog" else ("file", hashlib.sha256(origin[1].encode()).hexdigest())
    reg = _REGISTRIES.get(key)
    if reg is not None:
        return reg
    from .claims import load_catalog, load_claims_file
    if origin[0] == "catalog":
        reg = load_catalog()
    else:
        d = Path(tempfile.gettempdir()) / f"stiefelsym-dask-{os.getuid() if hasattr(os, 'getuid') else 0}"
        d.mkdir(parents=True, exist_ok=True)
        path = d / f"claims_{key[1][:16]}.py"
        if not path.is_file():
            tmp = path.with_suffix(f".{os.getpid()}.tmp")
            tmp.write_text(origin[1], encoding="utf-8")
            os.replace(tmp, path)
        reg = load_claims_file(path)
    _REGISTRIES[key] = reg
    return reg


def run_remote(spec: dict[str, Any]) -> Outcome:
    """One run on a dask worker, in a budgeted forked process: the pool's raw outcome."""
    from . import runner
    from .pool import WorkerPool
    from .methods import _describe
    claim = _registry(tuple(spec["origin"])).get(spec["claim"])
    claims = [claim]
    task = (0, spec["n"], spec["r"], spec["method"], spec["correction"])
    runner._preload([task])
    memory = None if spec["memory"] is None else int(spec["memory"] * GIB)
    timeout = spec["timeout"]
    pool: WorkerPool

    def execute(t: tuple) -> Result:
        return runner._execute(claims, spec["seed"], spec["hard"], timeout, pool.forking, t)

    with WorkerPool(execute, workers=1, timeout=timeout, memory=memory, describe=_describe) as pool:
        for _, outcome in pool.run([task]):
            return outcome
    return Outcome("error", message="the run produced no outcome")


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
    from . import runner
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

    def spec(task: tuple) -> dict[str, Any]:
        ci, n, r, m, k = task
        return {"origin": origins[ci], "claim": claims[ci].id, "n": n, "r": r, "method": m, "correction": k,
                "seed": seed, "hard": hard, "timeout": float(timeout), "memory": memory}

    def deliver(res: Result) -> None:
        results.append(res)
        if on_result is not None:
            on_result(res)

    def run(batch: list[tuple]) -> Iterable[tuple[int, Outcome]]:
        # pure=False: a run is never deduplicated or cached by the scheduler
        futures = [client.submit(run_remote, spec(t), pure=False, key=f"stiefelsym-run-{uuid.uuid4().hex}")
                   for i, t in enumerate(batch)]
        try:
            for i, fut in enumerate(futures):
                try:
                    outcome = fut.result()
                except Exception as exc:  # noqa: BLE001 - the dask worker was lost, or the task raised
                    outcome = Outcome("error", message=f"the cluster did not complete the run: "
                                                       f"{type(exc).__name__}: {exc}")
                if not isinstance(outcome, Outcome):
                    outcome = Outcome("error", message="the cluster returned something else than an outcome")
                yield i, outcome
        finally:
            client.cancel([f for f in futures if not f.done()])

    try:
        runner.run_with_corrections(run, tasks, claims, seed, hard, deliver)
    finally:
        if own:
            client.close()
    return results


def verifier(address: str) -> Callable[..., list[Result]]:
    """A function with the signature of ``runner.verify`` that runs the plan on the cluster at
    ``address`` (used by ``stiefelsym verify --scheduler ADDRESS``)."""
    def run(claims: list[Claim], **kw: Any) -> list[Result]:
        return verify(claims, address=address, **kw)
    return run
