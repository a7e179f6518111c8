"""The library entry point: :func:`verify` runs claims as ``stiefelsym verify`` does and returns
the result records (a :class:`~stiefelsym.results.ResultList`)."""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Iterable, Sequence, Union

from stiefelsym.claims import Claim, Registry, Size, load_catalog
from stiefelsym.run import rerun
from stiefelsym.run.pool import DEFAULT_MEMORY_GIB, DEFAULT_TIMEOUT
from stiefelsym.results import ResultList

PathLike = Union[str, "os.PathLike[str]"]
ClaimRef = Union[str, Claim]


def claims_files(paths: PathLike | Iterable[PathLike]) -> list[Path]:
    """Claims files: a directory stands for its ``*.py`` files (sorted; names starting with ``_``
    left out)."""
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    out: list[Path] = []
    for p in map(Path, paths):
        if p.is_dir():
            found = sorted(f for f in p.glob("*.py") if not f.name.startswith("_"))
            if not found:
                raise FileNotFoundError(f"the claims directory {p} holds no .py file")
            out += found
        else:
            out.append(p)
    return out


def load(files: PathLike | Iterable[PathLike] = (), catalog: bool | None = None,
         sizes: Iterable[tuple[int, int] | Size] = (), only: Iterable[str] | None = None) -> Registry:
    """The claims of ``files`` (files or directories), followed by the catalog's when ``catalog``
    (default: only when no file is given).  An id defined twice is refused (ValueError).

    A file is imported and its claims traced in child processes, as ``stiefelsym verify --claims``
    does (:func:`stiefelsym.run.userfile.load_claims_isolated`): at the sizes each claim lists and at
    ``sizes`` (only the claims ``only`` names, when given); nothing of the file runs in the calling process.
    So a claim traced at fixed sizes (one that reads entries) is verified by :func:`verify` at those sizes only
    (ValueError at others, naming them); a claim traced with symbolic sizes serves every size.  To import a file in this process (its claims as written, e.g. to call their functions), use
    :func:`stiefelsym.load_claims_file`."""
    from stiefelsym.run.userfile import load_claims_isolated
    merged = Registry()
    paths = claims_files(files)
    wanted = list(sizes)
    origin: dict[str, str] = {}
    for f in paths:
        for c in load_claims_isolated(f, wanted, only):
            if c.id in merged:
                raise ValueError(f"claim {c.id!r} is defined twice (again in {f})")
            merged.add(c)
            origin[c.id] = str(f)
    merged.origin = origin
    with_catalog = catalog or (catalog is None and not paths)
    cat = load_catalog() if paths or with_catalog else None
    if paths and cat is not None:
        # a claim of a file with a catalog claim's id: its results say so (Result.shadows)
        merged.mark_shadowing(cat.ids())
    if cat is not None and with_catalog:
        for c in cat:
            if c.id not in merged:
                merged.add(c)
    return merged


def _size_text(text: str) -> tuple[int, int]:
    """An "n,r" text as the pair (n, r), read as ``--size`` reads it (ValueError otherwise, naming the text)."""
    from stiefelsym.sizerules import parse_size
    return parse_size(text)


def _plain_size(s: Any) -> Size:
    """A size as the plain (n, r) the run uses: each of n and r read once, and each an int (a subclass of a size or
    of int, which may answer differently when read again, is not taken as it is)."""
    n, r = (s.n, s.r) if isinstance(s, Size) else tuple(s) if isinstance(s, (tuple, list)) and len(s) == 2 else (s, None)
    if type(n) is not int or type(r) is not int:
        raise ValueError(f"a size is a pair of ints (n, r), not {s!r}")
    return Size(n, r)


def _check_arguments(methods: tuple, sizes: Any, seed: Any, timeout: Any, memory: Any, jobs: Any, budget: Any) -> None:
    """ValueError, naming the argument, for arguments of :func:`verify` the command line would refuse: a run of
    nothing (no method, an empty list of sizes) is not a green result."""
    from stiefelsym.run.pool import amount_problem
    if not methods:
        raise ValueError("methods names no method: give at least one of auto, exact, rational, modular, float, ball, "
                         "free")
    if sizes is not None and len(sizes) == 0:
        raise ValueError("sizes=[] names no size: give (n, r) pairs, or sizes=None for each claim's own sizes")
    if type(seed) is not int or seed < 0:
        raise ValueError(f"seed must be a non-negative int (the seed of every random choice of the run), not {seed!r}")
    if type(jobs) is not int or jobs < 1:
        raise ValueError(f"jobs must be an int >= 1 (the worker processes), not {jobs!r}")
    for name, x, optional in (("timeout", timeout, False), ("memory", memory, True), ("budget", budget, True)):
        if not (x is None and optional) and amount_problem(name, x):
            raise ValueError(amount_problem(name, x) + (" (or None: no limit)" if optional else ""))


def _check_traced_sizes(c: Claim, pairs: list[Size]) -> None:
    """ValueError for a claim of a claims file (``load(files=F)``) asked at a size its file was not traced at:
    no code of the file runs in this process, so each size of a run must be one its child computed the claim's
    graphs at (unless they have symbolic sizes), and its size condition (``where=``) and erratum sizes
    (``fails_at=``), which the child tabled at n <= 16 and at the sizes given to load()."""
    from stiefelsym.run.userfile import TracedFunction, _Lookup
    funcs = [f for f in [c.func] + [k.func for k in c.corrections] if isinstance(f, TracedFunction)]
    where = getattr(c.sizes, "where", None)

    def traced(n: int, r: int) -> bool:
        if isinstance(where, _Lookup) and not where.bounds_only and (n, r) not in where.table:
            return False
        if not c.sizes.admits(n, r):
            return True     # refused by the run as outside the statement
        if isinstance(c.fails_at, _Lookup) and (n, r) not in c.fails_at.table:
            return False
        return all(f.symbolic() or (n, r) in f.sizes() for f in funcs)
    missing = [s for s in pairs if 1 <= s.r <= s.n and not traced(s.n, s.r)]
    if missing:
        raise ValueError(
            f"claim {c.id!r} of a claims file was traced (its graphs, size condition and erratum sizes) in its file's "
            f"child process only at its own sizes and those given to load(), not at "
            f"{', '.join(f'({s.n},{s.r})' for s in missing)}: pass the sizes to load(files=..., sizes=[...]), or "
            f"verify({c.id!r}, files=..., sizes=...), which traces the file at the run's sizes")


def verify(claims: ClaimRef | Iterable[ClaimRef] | None = None, *,
           files: PathLike | Iterable[PathLike] = (),
           sizes: Sequence[tuple[int, int] | Size | str] | None = None,
           methods: str | Iterable[str] = ("auto",), seed: int = 0,
           timeout: float = DEFAULT_TIMEOUT, memory: float | None = DEFAULT_MEMORY_GIB, jobs: int = 1,
           budget: float | None = None, scheduler: str | None = None) -> ResultList:
    """Verify claims and return their results, in the order of the plan (then the corrections of
    a claim that fails as printed), exactly as ``stiefelsym verify`` computes them.

    ``claims``: claim ids, :class:`Claim` objects (from ``@claim``), or None for every claim of
    ``files`` (or the catalog when no file is given).  ``files``: claims files or directories of
    them.  ``sizes``: (n, r) pairs (default: each claim's own).  ``methods``: ``auto``, ``exact``,
    ``rational``, ``modular``, ``float``, ``ball``, ``free``.  ``timeout`` (seconds) and ``memory`` (GiB,
    None: no limit) are the budgets of each run, which runs in a forked worker process (``jobs``
    of them).  ``budget``: refuse, before anything runs, a run the cost model predicts to take
    longer (seconds).  ``scheduler``: the address of a dask.distributed scheduler.

    ``sizes`` takes ``"n,r"`` texts too, as ``--size`` does.

    Bad input (an unknown claim or method, a size outside a named claim's statement, a run beyond
    the budget) raises ValueError (KeyError for an unknown id); a claims file that cannot be loaded (not
    found, not Python, raising while imported, declaring no claim) raises :class:`stiefelsym.CatalogError`.  A
    claim that fails is a result, never an exception: see ``result.verdict`` and ``result.expected``, or
    ``results.ok``; each result's ``rerun`` is the command that runs it again (with ``--claims FILE`` for a claim
    of a file)."""
    from stiefelsym.run import runner
    from stiefelsym.methods import costmodel
    if isinstance(methods, str):
        methods = (methods,)
    methods = tuple(methods)
    sizes = None if sizes is None else list(sizes)
    _check_arguments(methods, sizes, seed, timeout, memory, jobs, budget)
    # numpy's numbers are amounts too: the run and its records see plain floats
    timeout = float(timeout)
    memory, budget = (None if x is None else float(x) for x in (memory, budget))
    pairs: list[Size] | None = None if sizes is None else [
        _plain_size(_size_text(s) if isinstance(s, str) else s) for s in sizes]
    named = [claims] if isinstance(claims, (str, Claim)) else (None if claims is None else list(claims))
    ids = [c for c in named or () if isinstance(c, str)]
    if named and files and not ids:
        raise ValueError("files= names the claims files whose claims are verified by id (or all of them when no "
                         "claim is named); the claim objects given are verified as they are: name the file's claims "
                         "by id, or drop files=")
    registry = Registry()
    if named is None or ids:
        wanted = list(pairs or ())
        only = ids or None      # the claims named: only they are traced at the run's sizes
        registry = load(files, catalog=False, sizes=wanted, only=only) if files else Registry()
        if not len(registry) or any(i not in registry for i in ids):
            registry = load(files, catalog=True, sizes=wanted, only=only)
    selected = [registry.get(c) if isinstance(c, str) else c for c in (named if named is not None else registry)]
    if not selected:
        raise ValueError("no claims to verify (0 claims loaded)")
    ids_seen: dict[str, Claim] = {}
    for c in selected:
        if ids_seen.setdefault(c.id, c) is not c:
            raise ValueError(f"two different claims with the id {c.id!r} (a run, its records and its rerun commands "
                             "name a claim by its id): give each claim an id of its own")
    size_list = pairs
    for c in named or ():
        if isinstance(c, Claim) and pairs is not None and set(methods) - {"free"}:
            _check_traced_sizes(c, pairs)
    for c in selected:
        for m in methods:
            if m == "free":
                continue
            for s in size_list or list(c.sizes):
                if 1 <= s.r <= s.n and c.sizes.admits(s.n, s.r):
                    costmodel.check_memory(m, c, s.n, s.r, memory)
                    if budget is not None:
                        costmodel.check(m, c, s.n, s.r, budget)
    engine = runner.verify
    if scheduler is not None:
        from stiefelsym.ir.seal import verify as verify_engine
        from stiefelsym.run import distributed
        # nothing is evaluated in this process then, so the engine (the cluster's client included) is checked
        # here against the seal of a claims file loaded into it
        verify_engine("before the run was sent to the cluster")
        engine = distributed.verifier(scheduler)
    results = engine(selected, sizes=size_list, methods=methods, seed=seed, timeout=timeout, memory=memory,
                     jobs=jobs, strict_sizes=named is not None)
    budgets = rerun.budget_options(timeout, budget, memory)
    for r in results:           # the command that runs a claim of a file again names the file, and the budgets
        registry.rerun_naming_file(r)
        rerun.with_budgets(r, budgets)
    return ResultList(results)
