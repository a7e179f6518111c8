"""A user's claims file, imported and traced in fresh interpreters only.

A claims file is Python: once imported into a process, its code can reach
anything there (profile hooks, the engine's memos and containers, the fields of
its own claims, module state shared by its claims, the process's memory, command
line and environment).  So the process that plans and verifies never imports it,
and the process that does knows nothing of the run.  :func:`load_claims_isolated`:

1. spawns a fresh interpreter (:mod:`stiefelsym.run.sandbox`: neutral argv, minimal
   environment, confined in namespaces where the platform has them) and gives it
   on its standard input the file's path, *no size*, no budget of the run: the first
   phase.  It imports the file (:func:`stiefelsym.claims.load_claims_file`:
   sealed engine, deadline, standard output to standard error) and, for each
   claim, job by job, forks a child that does that job alone (its metadata, or one function
   traced at one key: no graph can depend on another claim, correction or size having been
   traced before it), twice and compared as in
   :func:`stiefelsym.ir.compile_claim`, with symbolic sizes and, only when that
   trace is refused, at the sizes its size statement lists, and the same for each
   correction (a function with a graph of symbolic sizes is never traced at a
   number); the child also evaluates the claim's metadata callables (the size
   condition, the erratum sizes) into tables (n <= 16 and the listed sizes);
2. only when the command asks for sizes that the first phase could not answer (a
   function refused with symbolic sizes: it used a size's number, so it has no
   proof for every n, r; or a size beyond the tables) a second interpreter is
   spawned the same way; it reads no size itself: one child at a time reads its
   own size and answers (:func:`_second_phase`, :func:`_by_size`,
   :func:`_tracer_by_size`: each imports the file itself, and what a function
   traced at a size sees depends on the file and that size, never on the run's
   other sizes); what they send adds rows and graphs, never replaces one;
3. the interpreters send back pure data as JSON: the metadata fields, the sizes as
   an explicit list with the bounds and an admits table, the erratum table, and
   per (size | symbolic) either the graph's state or the refusal (exception class
   name, message, the claim's file and line);
4. this process decodes it with a strict decoder (:func:`_value`: only int, str,
   bool, None, lists, tuples, Fraction and the IR's Ref, Size and Named come out;
   nothing is unpickled) and builds ordinary :class:`~stiefelsym.claims.Claim`
   objects: the function is a :class:`TracedFunction` that replays the graph
   traced at the size the engine's tracer asks for (engine code only, so the
   graph is re-typed and its digest recomputed here), re-raises the recorded
   refusal, or raises :class:`NoGraph` (verdict ``error``) at a size or
   realization it has no graph for; ``where`` and ``fails_at`` are table lookups;
   ``reviewed`` is always False; the confinement the file was traced under is the
   function's ``confinement`` (a record of a file traced without namespaces says so).

Where ``os.fork`` or ``os.posix_spawn`` is not available the file is loaded
in-process as before (:func:`~stiefelsym.claims.load_claims_file`).
"""
from __future__ import annotations

import builtins
import dataclasses
import gc
import itertools
import json
import os
import signal
import sys
import tempfile
import time
import traceback
from fractions import Fraction
from pathlib import Path
from typing import Any, Callable, Iterable, Sequence

from stiefelsym.run.pool import DEFAULT_MEMORY_GIB, GIB, write_fully
from stiefelsym.run.confine import ProcessesLeft
from stiefelsym.run.isolate import next_chunk
from stiefelsym.claims import (IMPORT_SECONDS, CatalogError, Claim, ClaimTimeout, Correction, Registry, Size, SizeSpec,
                               claims_file_missing, load_claims_file)
from stiefelsym.ir import GraphUnavailable

#: sizes n <= this get an entry in the admits table (the free method checks a declared r up to here)
TABLE_N = 16
#: at most this many sizes in a claim's size statement
MAX_SIZES = 2000
#: the tracing budgets: seconds the tracing of one function at one size may take, and the address space (GiB)
#: of the process that traces it; and seconds the whole file may take.  They are the engine's, the same in
#: every run: the run's budgets (--timeout, --memory) never reach the interpreter, where the file could read
#: them (its frames, its objects, getrlimit) and trace another graph in another run
CLAIM_SECONDS = 300.0
CLAIM_MEMORY_GIB = DEFAULT_MEMORY_GIB
FILE_SECONDS = 3600.0
#: seconds a claim's metadata (its size statement and erratum sizes, each call of which has METADATA_SECONDS)
#: may take in all in its child, which is killed after them
META_SECONDS = 60.0
#: seconds past the import's own deadline (IMPORT_SECONDS, an alarm the file's code could catch) after which the
#: process that imports the file is killed
IMPORT_GRACE_SECONDS = 10.0
#: seconds the interpreter that traces a file may take, beyond the import's deadline and its grace, from its
#: confinement line (or an answer) to the end of an import of the file (the engine's own import, a fork): past
#: them the verifying process kills it (a file whose code holds the interpreter's lock in C stops the watch too)
IMPORT_START_SECONDS = 30.0
#: seconds past CLAIM_SECONDS after which the verifying process kills the interpreter that traces a file when no
#: tracing of a function at a size has ended (:data:`stiefelsym.run.sandbox.BEAT`) and no answer come: each has
#: CLAIM_SECONDS in the tracing process, whose own deadline a thread of the file holding the lock in C would stop
BEAT_GRACE_SECONDS = 30.0
#: seconds a job's own import of the file may take (every job of a file imports it in a child of its own:
#: :func:`_jobs_lines`), its deadline and the grace past it
IMPORT_BUDGET = IMPORT_SECONDS + IMPORT_GRACE_SECONDS
#: what a job's child writes when its import of the file has ended (before its one JSON line)
IMPORTED_MARK = b"."
#: the exit status of a process whose import of the file outlived its watch (_watched)
IMPORT_EXIT = 7
#: at most this much of what the file's processes print is shown
CAPTURE_BYTES = 1 << 22


class NoGraph(GraphUnavailable):
    """The claims file was traced in a child process, and not at the size or realization asked for."""


class EngineStateChanged(RuntimeError):
    """The engine's state in a tracing interpreter is not what the engine made of it (the file changed it)."""


class TraceEnded(RuntimeError):
    """The claim's tracing in its claims file's child process ran out of time or ended its process: no graph,
    and no reading of the claim either (a run that meets it is ``inconclusive`` when the time budget ran out,
    else an ``error``; never a claim that merely does not run on some backend)."""

    def __init__(self, message: str, timeout: bool = False) -> None:
        super().__init__(message)
        self.timeout = timeout


# --------------------------------------------------------------------------- the wire format

def _enc(v: Any) -> Any:
    """An IR value as JSON (tagged where JSON has no such type)."""
    from stiefelsym.ir.graph import Named, Ref, Size as GSize
    t = type(v)
    if v is None or t in (bool, int, str):
        return v
    if t is Ref:
        return {"r": v[0]}
    if t is tuple:
        return {"t": [_enc(x) for x in v]}
    if t is list:
        return {"l": [_enc(x) for x in v]}
    if t is Fraction:
        return {"f": [v.numerator, v.denominator]}
    if t is GSize:
        return {"s": [v.k, v.d, v.value]}
    if t is Named:
        return {"q": v.qualname}
    raise TypeError(f"not a value of the IR: {t.__name__}")


class WireError(ValueError):
    """What a child sent is not the data this module expects."""


def _value(x: Any) -> Any:
    """The strict decoder of :func:`_enc`: int, str, bool, None, lists, tuples, Fraction, Ref, Size, Named."""
    from stiefelsym.ir.graph import Named, Ref, Size as GSize
    t = type(x)
    if x is None or t in (bool, int, str):
        return x
    if t is not dict or len(x) != 1:
        raise WireError("a value that is not of the IR")
    (tag, v), = x.items()
    if tag == "r" and type(v) is int and v >= 0:
        return Ref(v)
    if tag in ("t", "l") and type(v) is list:
        items = [_value(y) for y in v]
        return tuple(items) if tag == "t" else items
    if tag == "f" and type(v) is list and len(v) == 2 and all(type(y) is int for y in v) and v[1] > 0:
        return Fraction(v[0], v[1])
    if tag == "s" and type(v) is list and len(v) == 3 and type(v[0]) is int and v[1] in ("n", "r") \
            and (v[2] is None or type(v[2]) is int):
        return GSize(v[0], v[1], v[2])
    if tag == "q" and type(v) is str:
        return Named(v)
    raise WireError(f"a value of the IR with an unknown tag {tag!r}")


def _no_float(text: str) -> Any:
    raise WireError("a number that is not an int")


def _loads(data: bytes) -> Any:
    try:
        return json.loads(data.decode("utf-8"), parse_float=_no_float, parse_constant=_no_float)
    except (UnicodeDecodeError, json.JSONDecodeError, RecursionError) as exc:
        raise WireError(f"not JSON: {exc}") from None


def _slips(v: list) -> tuple[str, ...]:
    """A claim's slips of the paper, as the file's decorator gave them (strings; the claim validates them)."""
    if not all(type(x) is str for x in v):
        raise WireError("a slip that is not a string")
    return tuple(v)


def _get(d: Any, key: str, *types_: type, optional: bool = False) -> Any:
    if type(d) is not dict:
        raise WireError("a record that is not a mapping")
    if key not in d:
        if optional:
            return None
        raise WireError(f"the field {key!r} is missing")
    v = d[key]
    if optional and v is None:
        return None
    if type(v) not in types_:
        raise WireError(f"the field {key!r} is a {type(v).__name__}")
    return v


def _exact_pairs(pairs: list) -> tuple[tuple[int, int], ...]:
    if not all(type(p) is list and len(p) == 2 and all(type(x) is int for x in p) for p in pairs):
        raise WireError("the field 'exact_max_r' is not a list of [n, r] pairs")
    return tuple((p[0], p[1]) for p in pairs)


# --------------------------------------------------------------------------- the children

def _graph_state(g: Any) -> Any:
    ops, args, output, refusals, fns, sizes = g.__getstate__()
    return {"ops": list(ops), "args": [_enc(a) for a in args], "output": _enc(output), "fns": fns,
            "sizes": None if sizes is None else list(sizes)}


def _refusal(exc: BaseException) -> dict:
    tb = getattr(exc, "_first_traceback", None) or exc.__traceback__
    # (not the engine's frames, nor generated code such as a dataclass's __init__, whose file is "<string>")
    frames = [f for f in traceback.extract_tb(tb) if "/stiefelsym/" not in f.filename and not f.filename.startswith("<")]
    where = [frames[-1].filename, frames[-1].lineno or 1] if frames else None
    try:
        message = str(exc)
    except Exception:   # noqa: BLE001 - a message that does not print
        message = "(no message)"
    if type(exc) is RecursionError:
        from stiefelsym.ir import recursion_text
        message = recursion_text()
    name = type(exc).__name__
    if not _genuine(type(exc)):
        # a class of the file's own that takes the name of an engine's or a builtin exception (TraceRefused,
        # MemoryError): recorded under its name, never replayed as that exception
        name, message = "ClaimException", f"{name} (a class of the claims file's own): {message}"
    return {"error": [name, message], "at": where}


def _genuine(cls: type) -> bool:
    """Whether an exception class is the builtin or the engine's class of its name (not a claims file's class
    named so)."""
    from stiefelsym.ir import NotDeterministic, TraceRefused
    from stiefelsym.ir.replay import ReplayError
    from stiefelsym.ir.seal import EngineChanged
    name = cls.__name__
    return cls is getattr(builtins, name, None) or cls in (TraceRefused, NotDeterministic, ReplayError, ClaimTimeout,
                                                           NoGraph, EngineStateChanged, EngineChanged)


def _trace_one(func: Callable, realization: str, key: Any) -> Any:
    """The graph's state, or the refusal, of one function at one key (None: symbolic sizes)."""
    from stiefelsym.ir import Graph, _compile
    from stiefelsym.ir.seal import verify
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[realization]
    constraints = (cons.name, cons.build)
    # the file was imported in this interpreter: no graph is taken from its caches (cached=False), and the
    # tracer's memos must be what the engine made of them (memo_problems), before and after the tracing
    from stiefelsym.ir.trace import memo_problems
    try:
        if memo_problems():
            raise EngineStateChanged(f"the tracer's memos were changed before the tracing: {memo_problems()[0]}")
        if key is None:
            g = _compile(func, None, None, constraints, cached=False)
        elif key[0] == "r":      # the family r = k, every n >= k (a claim's free_max_r)
            from stiefelsym.ir import SizeFamily
            g = _compile(func, None, None, constraints, family=SizeFamily(key[1], key[1], one_of_every_r=True),
                         cached=False)
        else:
            g = _compile(func, key[0], key[1], constraints, cached=False)
        if memo_problems():
            raise EngineStateChanged(f"the tracer's memos were changed while the claim was traced: {memo_problems()[0]}")
        # what encodes the graph and writes the answer (Fraction's members, json) as the engine sealed it: claim
        # code ran in this process while it was traced
        verify("tracing a claim of the file")
    except BaseException as exc:   # noqa: BLE001 - SystemExit, KeyboardInterrupt, anything: recorded
        return _refusal(exc)
    return _graph_state(g) if isinstance(g, Graph) else _refusal(g)


def _table(f: Callable[[int, int], Any], pairs: Iterable[tuple[int, int]]) -> list:
    out = []
    for n, r in pairs:
        try:
            out.append([n, r, bool(f(n, r))])
        except Exception as exc:    # noqa: BLE001 - raised again where the engine asks
            out.append([n, r, _refusal(exc)])
    return out


def _claim_data(c: Claim, needed: Sequence[tuple[int, int]] = ()) -> dict:
    """Everything the verifying process needs of one claim (run in the claim's own child; the first phase
    passes no ``needed`` sizes: it knows none)."""
    spec = c.sizes
    listed = []
    for z in itertools.islice(iter(spec), MAX_SIZES + 1):
        if not isinstance(z, Size) or type(z.n) is not int or type(z.r) is not int:
            raise ValueError(f"claim {c.id}: its sizes are not Size(n, r) of ints")
        listed.append((z.n, z.r))
    if len(listed) > MAX_SIZES:
        raise ValueError(f"claim {c.id}: more than {MAX_SIZES} sizes")
    top = max([TABLE_N] + [n for n, _ in listed] + [n for n, _ in needed])
    domain = [(n, r) for n in range(1, top + 1) for r in range(1, n + 1)]
    admits = _table(spec.admits, domain)
    admitted = [(n, r) for n, r, v in admits if v is True]
    traced = list(dict.fromkeys(listed + [p for p in needed if p in set(admitted)]))
    fails = None if c.fails_at is None else _table(c.expects_failure, list(dict.fromkeys(admitted + listed)))
    try:
        path = os.path.realpath(sys.modules[c.func.__module__].__file__ or "")
    except (AttributeError, KeyError, TypeError):
        path = ""
    line = getattr(getattr(c.func, "__code__", None), "co_firstlineno", 0)
    return {
        "id": c.id, "paper": list(c.paper), "kind": c.kind, "section": c.section, "statement": c.statement,
        "title": c.title, "realization": c.realization, "expect": c.expect, "exact_max_n": c.exact_max_n,
        "exact_max_r": [list(p) for p in c.exact_max_r], "exact_corank": [list(p) for p in c.exact_corank],
        "erratum": c.erratum, "place": c.place, "slips": [str(x) for x in c.slips], "equivariance": c.equivariance,
        "source": c.source, "path": path,
        "line": line if type(line) is int else 0, "name": getattr(c.func, "__name__", c.id),
        "sizes": {"list": [list(p) for p in listed], "n_min": spec.n_min, "r_min": spec.r_min,
                  "r_max": spec.r_max, "n_max": spec.n_max, "r_is_n": bool(spec.r_is_n),
                  "r_in": [v if v == "n" else int(v) for v in (getattr(spec, "r_in", ()) or ())],
                  "condition": spec.condition, "where": spec.where is not None or type(spec) is not SizeSpec or bool(getattr(spec, "r_in", ())),
                  "fields_first": type(spec) is SizeSpec, "admits": admits},
        "fails_at": fails,
        "free_max_r": c.free_max_r,
        # the families r = k <= free_max_r (up to the largest n of the run): a function refused with symbolic sizes
        # may have a graph there, which the dimension-free method proves (stiefelsym.methods.specialise)
        "keys": [None] + [["r", k] for k in range(1, min(c.free_max_r, top) + 1)] + [list(p) for p in traced],
        "corrections": [{"description": k.description, "changes": k.changes, "expect": k.expect,
                         "exact_max_r": [list(p) for p in k.exact_max_r],
                         "exact_corank": [list(p) for p in k.exact_corank]} for k in c.corrections],
    }


def _claim_more(c: Claim, more: dict) -> dict:
    """The second phase's data of one claim: its size condition and erratum sizes at the sizes ``table`` (beyond
    the first phase's table), and the keys its functions ``funcs`` (refused with symbolic sizes) are traced at:
    the sizes ``trace`` (admitted, per the first phase's table) and those of ``table`` it admits."""
    table = [(n, r) for n, r in more.get("table", [])]
    admits = _table(c.sizes.admits, table)
    admitted = [(n, r) for n, r, v in admits if v is True]
    fails = None if c.fails_at is None else _table(c.expects_failure, admitted)
    keys = list(dict.fromkeys([tuple(p) for p in more.get("trace", [])] + admitted))
    return {"id": c.id, "admits": admits, "fails_at": fails,
            "keys": [list(p) for p in keys] if more.get("funcs") else [], "funcs": list(more.get("funcs", []))}


def _limit_memory(memory: int | None) -> None:
    if memory is None:
        return
    import resource
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = memory if hard == resource.RLIM_INFINITY else min(memory, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def _die_with_parent() -> None:
    from stiefelsym.run.pool import _death_signal_setup
    prctl = _death_signal_setup()
    if prctl:
        prctl(1, signal.SIGKILL)                # PR_SET_PDEATHSIG


def _not_dumpable(what: str) -> None:
    """Make this process not dumpable (PR_SET_DUMPABLE 0, inherited by its forks): a process of the same user, a
    child that runs a claims file's code included, can then neither read nor write its memory (process_vm_readv,
    process_vm_writev, ptrace, /proc/PID/mem)."""
    import ctypes
    if ctypes.CDLL(None, use_errno=True).prctl(4, 0, 0, 0, 0) != 0:       # PR_SET_DUMPABLE, 0
        raise OSError(ctypes.get_errno(), f"{what} could not be made non-dumpable")


def _jobs_lines(path: str, ids: list, cid: str, more: dict | None, jobs: list, start: int, memory: int | None,
                wfd: int) -> None:
    """A child: the job ``start`` of claim ``cid`` (its metadata, or one function traced at one key), one JSON
    line.  Each job has a child of its own, forked from a process that never imported the file, and imports the
    file itself: what one function traced at one key sees is the file and that key, never another job (a
    correction traced after the printed claim, a size after another), whatever state claim code keeps in its
    modules, in hooks the import registered (``os.register_at_fork``) or in memory, pipes or descriptors it made
    (stop 83's sweep: an import shared by the jobs let an at-fork hook count them, and an anonymous shared
    mapping carry a flag from one job to the next).  An import that does not register the same claims in the
    same order as the first (a file whose import is not deterministic) gives no job."""
    _die_with_parent()
    _limit_memory(memory)

    def write(obj: Any) -> None:
        write_fully(wfd, json.dumps(obj).encode() + b"\n")
    try:
        reg = _import_bounded(path)
    except Exception as exc:    # noqa: BLE001 - reported as the file's error
        write({"failed": f"importing the file again for one job: {type(exc).__name__}: {exc}"})
        return
    if [k.id for k in reg] != ids:
        write({"failed": "importing the file again for one job registered other claims (its import is not "
                         "deterministic): no graph of it is taken"})
        return
    write_fully(wfd, IMPORTED_MARK + b"\n")     # the job's own budget starts now
    c = reg.get(cid)
    job = jobs[start]
    if job[0] == "meta":
        try:
            meta = _claim_data(c) if more is None else _claim_more(c, more)
        except Exception as exc:    # noqa: BLE001 - reported as the file's error
            write({"failed": f"{type(exc).__name__}: {exc}"})
            return
        write({"meta": meta, "shape": {"realization": c.realization, "corrections": len(c.corrections)}})
        return
    _, f, key = job
    funcs = [c.func] + [k.func for k in c.corrections]
    write({"job": _trace_one(funcs[f], c.realization, key)})


def _job_line(line: bytes, key: str) -> dict | None:
    """The job's answer in a line of its pipe: a JSON object with ``key`` or "failed"; None for any other line
    (what the file's code wrote on the descriptors it reaches while it was imported: the progress lines of the
    verifying process, or anything else, are not an answer)."""
    try:
        item = json.loads(line)
    except ValueError:
        return None
    return item if type(item) is dict and (key in item or "failed" in item) else None


def _traced_at_no_size(out: dict) -> bool:
    """Whether a function's outcome with symbolic sizes ends its tracing: a graph there is its graph at every
    size; a function found not deterministic there is traced at no size either (its later calls may agree)."""
    return "error" not in out or _not_deterministic(out)


def _skipped(job: tuple, has_free: dict) -> bool:
    """Whether a job is not done: the function at a fixed size when it has a graph with symbolic sizes
    (that graph is its graph at every size, and it is never traced at a number: see
    :func:`stiefelsym.ir._compile`).  Asked alike by the grandchild and by its parent."""
    return job[0] == "f" and job[2] is not None and has_free.get(job[1], False)


def _next_job(jobs: list, i: int, has_free: dict) -> int:
    while i < len(jobs) and _skipped(jobs[i], has_free):
        i += 1
    return i


def _trace_jobs(meta: dict, shape: dict) -> list:
    """(f, key) for the claim's function (f = 0) and each correction (or the functions ``funcs`` of the second
    phase), at every key of the metadata (``shape``: the claim's realization and number of corrections, sent
    with the metadata by the job that imported the file)."""
    from stiefelsym.scene import REALIZATIONS
    if shape.get("realization") not in REALIZATIONS:
        return []
    count = shape.get("corrections", 0)
    keys = [None if k is None else tuple(k) for k in meta["keys"]]      # (n, r) or ("r", k)
    funcs = meta.get("funcs", range(1 + count))
    return [("f", f, k) for f in funcs if type(f) is int and 0 <= f <= count for k in keys]


#: in the tracer process, writes a BEAT line to the verifying process (:func:`_tracer`); None elsewhere
_BEAT: Callable[[], None] | None = None


def _beat() -> None:
    if _BEAT is not None:
        _BEAT()


def _run_claim(path: str, ids: list, cid: str, more: dict | None, timeout: float, memory: int | None) -> dict:
    """In the tracer process (which never imports the file): the metadata and the graphs of claim ``cid``
    (``more``: the second phase's, see :func:`_claim_more`), each function traced at each key in a child of its
    own that imports the file (one at a time, so that no job sees what another left: :func:`_jobs_lines`).  A key
    whose tracing ran out of time or died is recorded as such."""
    jobs: list = [("meta",)]
    meta: dict | None = None
    results: list = []
    has_free: dict = {}
    i = 0
    while i < len(jobs):
        with _Between():     # a process the child left ends with it (the next job sees none)
            pid, rfd, buf = _child({"do": "job", "path": path, "ids": ids, "cid": cid, "more": more, "job": jobs[i],
                                    "memory": memory})
            timed_out = done = False
            # the job's own import first, under its deadline; then the job's budget
            deadline, imported = time.monotonic() + IMPORT_BUDGET, False
            try:
                while i < len(jobs) and not done:
                    chunk = next_chunk(rfd, deadline) if b"\n" not in buf else b""
                    if chunk is None:
                        timed_out = True
                        break
                    if not chunk and b"\n" not in buf:
                        break
                    buf += chunk
                    while b"\n" in buf and not done:
                        line, buf = buf.split(b"\n", 1)
                        if line == IMPORTED_MARK:
                            if not imported:    # the job's own budget starts (and the import is progress)
                                imported = True
                                deadline = time.monotonic() + (META_SECONDS if jobs[i][0] == "meta" else timeout)
                                _beat()
                            continue
                        item = _job_line(line, "meta" if jobs[i][0] == "meta" else "job")
                        if item is None:    # not the job's line: something the file's code wrote on the pipe
                            _forward(line)
                            continue
                        done = True         # the child's one line: its job is done
                        _beat()
                        if "failed" in item:
                            raise ValueError(item["failed"])
                        if jobs[i][0] == "meta":
                            meta = item["meta"]
                            jobs += _trace_jobs(meta, item.get("shape", {}))
                        else:
                            _, f, key = jobs[i]
                            if key is None:
                                has_free[f] = _traced_at_no_size(item["job"])
                            results.append([f, None if key is None else list(key), item["job"]])
                        i = _next_job(jobs, i + 1, has_free)
            finally:
                _end(pid, rfd, buf, wait=not timed_out and i >= 0)
        _beat()         # the job that ran out of time or died has ended too
        if done:
            continue    # the next job, in a grandchild of its own
        if i >= len(jobs):
            break
        if jobs[i][0] == "meta":
            raise ValueError("its size statement or erratum sizes did not finish (the process died or ran out "
                             "of time)")
        _, f, key = jobs[i]
        mark = {"budget": "timeout"} if timed_out else {"budget": "died", "how": _status_text(pid)}
        results.append([f, None if key is None else list(key), mark])
        i += 1
        if timed_out:       # the function's other keys: not tried again (one budget per function)
            skipped = {"budget": "timeout", "after": "symbolic" if key is None else list(key)}
            while i < len(jobs) and jobs[i][1] == f:
                _, f2, k2 = jobs[i]
                results.append([f2, None if k2 is None else list(k2), skipped])
                i += 1
        i = _next_job(jobs, i, has_free)
    assert meta is not None
    del meta["keys"]
    if more is not None:
        meta["results"] = results
        return meta
    meta["graphs"] = [[k, e] for f, k, e in results if f == 0]
    for j, corr in enumerate(meta["corrections"], 1):
        corr["graphs"] = [[k, e] for f, k, e in results if f == j]
    return meta


_STATUS: dict[int, str] = {}


def _status_text(pid: int) -> str:
    return _STATUS.pop(pid, "the process vanished")


def _end(pid: int, rfd: int, buf: bytes, wait: bool) -> None:
    """A job's end: its pipe read to its end (``wait``: for a moment, the job having answered; else not at all),
    what the file printed there passed on, and the job's wait status, which its starter writes last, kept for
    :func:`_status_text`; a starter that has not written it by then is killed (and with it the job)."""
    status = None
    try:
        deadline = time.monotonic() + (1.0 if wait else 0.0)
        while wait:
            chunk = next_chunk(rfd, deadline)
            if not chunk:
                break
            buf += chunk
        for line in buf.split(b"\n"):
            if line.startswith(STATUS_MARK) and line[len(STATUS_MARK):].isdigit():
                status = int(line[len(STATUS_MARK):])
            elif line:
                _forward(line)
    finally:
        os.close(rfd)
    if status is None:
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
        _STATUS[pid] = "killed"
    elif os.WIFSIGNALED(status):
        _STATUS[pid] = f"killed by {signal.Signals(os.WTERMSIG(status)).name}"
    else:
        _STATUS[pid] = f"exited with status {os.WEXITSTATUS(status)}"


def _import_bounded(path: str) -> Registry:
    """The file imported (:func:`~stiefelsym.claims.load_claims_file`, under its deadline IMPORT_SECONDS), in a
    process ended IMPORT_GRACE_SECONDS later if the import has not ended (:func:`_watched`)."""
    from stiefelsym.claims import IMPORT_SECONDS
    return _watched(lambda: load_claims_file(path), IMPORT_SECONDS + IMPORT_GRACE_SECONDS,
                    f"loading {path} did not end within {IMPORT_SECONDS:.0f} s (its code caught the time limit)")


def _watched(run: Callable[[], Any], seconds: float, what: str) -> Any:
    """``run()`` while a thread watches: the process ends (status IMPORT_EXIT) when it has not returned within
    ``seconds``.  A deadline is an alarm, which the file's code can catch (``except BaseException`` in a loop);
    the end of its process it cannot.  (Code that holds the interpreter's lock in C stops this thread too: the
    verifying process, which waits for the import's end, kills the interpreter then: :data:`IMPORT_START_SECONDS`.)
    The watch ends before the process forks."""
    import threading
    done = threading.Event()

    def watch() -> None:
        if not done.wait(seconds):
            os.write(2, f"stiefelsym: {what}: the process that ran it ends\n".encode())
            # _exit ends every thread of the process (a signal to itself would not: in its PID namespace the
            # sandbox's interpreter is process 1, which ignores a kill sent from inside)
            os._exit(IMPORT_EXIT)
    watcher = threading.Thread(target=watch, name="stiefelsym-watch", daemon=True)
    watcher.start()
    try:
        return run()
    finally:
        done.set()
        watcher.join()


def _tracer(path: str, more: dict | None, timeout: float, memory: int | None,
            mark: Callable[[bytes], None]) -> bytes:
    """The spawned interpreter's work (:func:`stiefelsym.run.sandbox.host`): the file's claims, listed by an import
    in a child of its own, then each claim traced job by job, each job in a child that imports the file itself
    (:func:`_run_claim`), forked from the zygote (:class:`_Zygote`), never from this process, which holds the
    answers: this process never imports the file, so that nothing the file's code leaves in a process
    (module state, hooks run at each fork, shared memory, descriptors) reaches a job from another.  ``more`` (the
    second phase): claim id -> what :func:`_claim_more` needs, and only those claims.  ``mark`` writes a line the
    verifying process waits for: :data:`stiefelsym.run.sandbox.IMPORTED` when the first import has ended,
    :data:`~stiefelsym.run.sandbox.BEAT` after each job of a claim (its metadata, one function at one size)."""
    from stiefelsym.ir.seal import import_engine, seal
    from stiefelsym.run.sandbox import BEAT, IMPORTED
    global _BEAT
    _die_with_parent()
    # no child reads or writes this process's memory (process_vm_writev, ptrace: stop 84's h1 changed an engine
    # method here from the listing child's import, before the fingerprint below was taken)
    _not_dumpable("the tracing process")
    sys.dont_write_bytecode = True      # an honest import here writes no byte code into the engine's folders
    try:
        os.setpgid(0, 0)        # its own process group: killed as a whole (with what the file started)
    except OSError:
        pass
    import_engine()                     # once, before the forks: each child imports the file itself
    # the engine's fingerprint, taken once here rather than in every job's child: each child has it before it
    # imports the file and checks the engine against it after (nothing of the file has run in this process)
    seal()
    _ZYGOTE[:] = [_Zygote()]            # every job's process is forked from it (before any job has answered)
    listed = _listed(path)
    if "error" in listed:
        return json.dumps({"error": listed["error"]}).encode()
    ids = listed["ids"]
    mark(IMPORTED)
    _BEAT = lambda: mark(BEAT)     # noqa: E731
    parts = []
    for cid in ids:
        if more is not None and cid not in more:
            continue
        try:
            data = json.dumps({"claim": _run_claim(path, ids, cid, None if more is None else more[cid], timeout,
                                                   memory)})
        except Exception as exc:    # noqa: BLE001 - reported as the file's error
            data = json.dumps({"failed": [cid, f"{type(exc).__name__}: {exc}"]})
        parts.append(data.encode())
    _flush()
    return b'{"claims": [' + b",".join(parts) + b"]}"


class _Zygote:
    """The process every job of a claims file is forked from (stop 85's second sweep): a child of the tracing process,
    forked before the first job, that never holds what a job answered, nor a job's request, process id or wait
    status.  The tracing process keeps the answers (the claims traced so far, each job's status): a job forked from
    it found them on its stack and in freed memory (W1), and the second phase's loop held the previous size's
    child (W2).  For each job the tracing process makes two fresh pipes (the request, the answer), hands the job's
    ends over a Unix socket (SCM_RIGHTS) and writes one byte to the zygote, which forks (:func:`_zygote`); the child
    takes the pipes itself, and the job reads its own request.  So every job starts from the same memory, with the
    same descriptors, none of which another job wrote to (standard output and error are its answer pipe; the
    tracing process passes what the file prints on to the capture)."""

    def __init__(self) -> None:
        import socket
        ctl_r, self.ctl_w = os.pipe()
        self.sock, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_DGRAM)
        _flush()
        pid = os.fork()
        if pid == 0:
            try:
                self.sock.close()
                os.close(self.ctl_w)
                _zygote(ctl_r, theirs.detach())
            finally:
                os._exit(0)
        self.pid = pid
        os.close(ctl_r)
        theirs.close()

    def alive(self) -> bool:
        try:
            return os.waitpid(self.pid, os.WNOHANG) == (0, 0)
        except ChildProcessError:
            return False

    def child(self, spec: dict) -> tuple[int, int, bytes]:
        """A job in a child of the zygote: the pid of its starter (:func:`_starter`), the answer pipe's end to
        read, and what was read past the pid's line."""
        import socket
        req_r, req_w = os.pipe()
        ans_r, ans_w = os.pipe()
        try:
            socket.send_fds(self.sock, [b"j"], [req_r, ans_w])
            os.write(self.ctl_w, b"j")
        finally:
            os.close(req_r)
            os.close(ans_w)
        try:
            write_fully(req_w, json.dumps(spec).encode() + b"\n")
        except OSError:
            pass            # the job ended before it read its request: the answer pipe says so
        finally:
            os.close(req_w)
        buf, deadline = b"", time.monotonic() + IMPORT_BUDGET
        while b"\n" not in buf:
            chunk = next_chunk(ans_r, deadline)
            if not chunk:
                os.close(ans_r)
                raise ValueError("a job's process did not start")
            buf += chunk
        line, rest = buf.split(b"\n", 1)
        if not line.startswith(PID_MARK):
            os.close(ans_r)
            raise ValueError("a job's process did not start")
        return int(line[len(PID_MARK):]), ans_r, rest


#: the first line of a job's answer pipe (written by its starter, before anything of the file runs) and the last
#: (after the job's process ended): its starter's pid, and the job's wait status
PID_MARK, STATUS_MARK = b"\x00pid ", b"\x00status "

_ZYGOTE: list = []


def _child(spec: dict) -> tuple[int, int, bytes]:
    """A job (``spec``: what :func:`_job_main` does) in a child of this tracing process's zygote (made here when there
    is none alive: the tracing process makes it before its first job, a process that calls a job directly, such as
    the tests, when it needs one)."""
    if not (_ZYGOTE and _ZYGOTE[-1].alive()):
        _ZYGOTE[:] = [_Zygote()]
    return _ZYGOTE[-1].child(spec)


def _zygote(ctl: int, sock: int) -> None:
    """The zygote's loop: one byte, one fork, until the tracing process ends.  Its memory is the same before every
    fork: the fork is libc's (no Python int of a child's pid is made here), the children are reaped by the kernel
    (SIGCHLD ignored: no wait status is read here), and the request and the pipes are taken by the child."""
    import ctypes
    _die_with_parent()
    from stiefelsym.run.sandbox import _close_inherited
    _close_inherited({ctl, sock})       # (standard input, output and error stay: the job replaces the last two)
    fork = ctypes.PyDLL(None).fork
    fork.restype, fork.argtypes = None, []
    me = os.getpid()
    signal.signal(signal.SIGCHLD, signal.SIG_IGN)
    gc.freeze()         # (the children's collections then leave the pages they share with this process alone)
    while os.read(ctl, 1):
        fork()
        if os.getpid() != me:
            signal.signal(signal.SIGCHLD, signal.SIG_DFL)
            code = 1
            try:
                code = _starter(ctl, sock)
            finally:
                os._exit(code)


#: unshare(2) flags: a user namespace (with all capabilities in it, so that the others need no privilege
#: outside), a PID namespace for the children, a mount namespace, an IPC namespace, a network namespace
CLONE_NEWUSER, CLONE_NEWPID, CLONE_NEWNS, CLONE_NEWIPC = 0x10000000, 0x20000000, 0x00020000, 0x08000000
CLONE_NEWNET = 0x40000000
JOB_NAMESPACES = CLONE_NEWUSER | CLONE_NEWPID | CLONE_NEWNS | CLONE_NEWIPC | CLONE_NEWNET
#: mount(2) flags of the job's own /proc (at least those of the /proc it hides: lock_down made it read-only)
PROC_FLAGS = 1 | 2 | 4 | 8      # MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC


def _own_stdin() -> None:
    """A standard input of this process's own, at its end (an empty pipe whose writing end is closed): the zygote's
    /dev/null was one open file of every job, and a lock a job set on it (F_OFD_SETLK) outlived the job, listed in
    /proc/locks to the jobs after it (stop 86's sweep).  (The confined file system has no /dev/null to open.)"""
    r, w = os.pipe()
    os.close(w)
    os.dup2(r, 0)
    os.close(r)


def _starter(ctl: int, sock: int) -> int:
    """A child of the zygote: it takes the job's pipes, writes its pid on the answer pipe, and forks the process that
    does the job.  In namespaces (:data:`stiefelsym.run.sandbox.CONFINED`) it enters new user, PID, mount, IPC and
    network namespaces first, so that the job is process 1 of a PID namespace of its own, with a /proc of its own, no
    System V object of another job and network counters of its own: every job sees the same process ids and no other
    process, neither the tracing process (whose /proc/1/status counted the jobs it had waited for) nor the pids the
    jobs before it took (stop 85's sweep: one function under two ids read that count), and /proc/net/snmp, which a
    datagram sent to the loopback raises, counts nothing of another job (stop 86's sweep).  A job whose namespaces
    cannot be made does not run.  It writes the job's wait status last, once the job's process (and, in its
    namespace, every process the job started) has ended; this process runs nothing of the file."""
    import ctypes
    import socket
    from stiefelsym.run import sandbox
    from stiefelsym.run.confine import Confined
    _die_with_parent()
    s = socket.socket(fileno=sock)
    _, fds, _, _ = socket.recv_fds(s, 1, 2)
    s.close()
    os.close(ctl)
    if len(fds) != 2:
        return 1
    req, ans = fds
    write_fully(ans, PID_MARK + str(os.getpid()).encode() + b"\n")
    libc = ctypes.CDLL(None, use_errno=True)
    alone = sandbox.CONFINED and libc.unshare(JOB_NAMESPACES) == 0
    if sandbox.CONFINED and not alone:
        # the interpreter runs in namespaces, so the job's own can be made; a job that could not have them does
        # not run outside them (it would see the tracing process and what the jobs before it left)
        err = ctypes.get_errno()
        write_fully(ans, json.dumps({"failed": "the job's own namespaces (user, PID, mount, IPC, network) could not "
                                               f"be made: {os.strerror(err)}"}).encode() + b"\n")
        return 1
    with Confined():        # (without namespaces: what the job leaves is ended here)
        job = os.fork()
        if job == 0:
            code = 1
            try:
                _die_with_parent()
                if alone and libc.mount(b"proc", b"/proc", b"proc", ctypes.c_ulong(PROC_FLAGS), None) != 0:
                    os._exit(1)         # no job in a namespace whose /proc still shows the tracing process
                _own_stdin()
                os.dup2(ans, 1)
                os.dup2(ans, 2)
                line = b""
                while not line.endswith(b"\n"):
                    chunk = os.read(req, 1 << 16)
                    if not chunk:
                        break
                    line += chunk
                os.close(req)
                _job_main(json.loads(line), ans)
                code = 0
            finally:
                _flush()
                os._exit(code)
        os.close(req)
        while True:
            try:
                _, status = os.waitpid(job, 0)
                break
            except InterruptedError:
                continue
    write_fully(ans, b"\n" + STATUS_MARK + str(status).encode() + b"\n")
    return 0


def _job_main(spec: dict, wfd: int) -> None:
    """A job, in the process :func:`_starter` forked: the listing of the file's claims, or one job of a claim."""
    if spec["do"] == "list":
        _listing(spec["path"], wfd)
    else:
        _jobs_lines(spec["path"], spec["ids"], spec["cid"], spec["more"], [spec["job"]], 0, spec["memory"], wfd)


def _listing(path: str, wfd: int) -> None:
    _die_with_parent()
    try:
        out: dict = {"ids": [c.id for c in _import_bounded(path)]}
    except CatalogError as exc:
        out = {"failed": str(exc)}
    except ProcessesLeft as exc:
        out = {"failed": f"{path}: {exc}"}
    write_fully(wfd, json.dumps(out).encode() + b"\n")


def _forward(line: bytes) -> None:
    """A line of a job's answer pipe that is not its answer nor the pipe's own: what the file's code printed, passed
    on to the capture (the tracing process's standard error)."""
    if line.startswith(PID_MARK) or line.startswith(STATUS_MARK) or line == IMPORTED_MARK:
        return
    try:
        write_fully(2, _shown(line) + b"\n")
    except OSError:
        pass


#: the control characters a file's print may not pass on to a terminal (all but the tab): C0, DEL and C1
_CONTROLS = {c: f"\\x{c:02x}" for c in [*range(0x20), 0x7F, *range(0x80, 0xA0)] if c != 0x09}


def _shown(line: bytes) -> bytes:
    """A line the file printed, as the verifying process passes it on: its control characters written as escapes
    (\\x1b ...), so that a file cannot move the cursor, clear or conceal a line of the run's own output in a
    terminal, or print a verdict line over it (stop 86's sweep, M1)."""
    text = line.decode("utf-8", "replace")
    return text.translate(_CONTROLS).encode("utf-8")


def _listed(path: str) -> dict:
    """{"ids": the ids of the file's claims, in order} from an import in a child of its own, or {"error": why}."""
    with _Between():        # what the import started ends with it: no process outlives it to the claims
        pid, rfd, buf = _child({"do": "list", "path": path})
        found = None
        deadline = time.monotonic() + IMPORT_BUDGET
        try:
            while found is None:
                while b"\n" in buf and found is None:
                    line, buf = buf.split(b"\n", 1)
                    found = _job_line(line, "ids")      # (other lines: the file's code wrote them)
                    if found is None:
                        _forward(line)
                if found is not None:
                    break
                chunk = next_chunk(rfd, deadline)
                if not chunk:
                    break
                buf += chunk
        finally:
            _end(pid, rfd, buf, wait=True)
    if found is None:
        how = _status_text(pid)
        if how.startswith("exited"):    # (it wrote no list: a file that ends its process, or writes for it)
            return {"error": f"importing {path} ended without listing its claims (its process {how})"}
        return {"error": f"loading {path} did not end within {IMPORT_BUDGET:.0f} s, or its process died ({how})"}
    if "failed" in found or type(found.get("ids")) is not list:
        return {"error": str(found.get("failed", "the file's claims could not be listed"))}
    return found


#: the exit status of a second phase's process that found no request left
NO_MORE = 5


def _tracer_by_size(path: str, requests: int, answer: int, timeout: float, memory: int | None) -> None:
    """The second phase's interpreter (:func:`stiefelsym.run.sandbox.host`): one child at a time, each forked before
    its request is read, reading its own request (one line of ``requests``: what :func:`_tracer` is asked at one
    size) and writing its answer (one line) to ``answer`` itself, until a child finds no request left.  This
    process reads no request and no answer, and is not dumpable (no child reads its memory or descriptors through
    /proc): a function traced at a size sees that size only, not the run's other sizes, nor how many there are.
    The loop runs in a process of its own (one thread), which forks with libc's fork, is told of a child's end by a
    byte on a pipe and lets the kernel reap it: it holds no Python int of a child's pid or wait status, which the
    next size's child, forked from it, would find (stop 85's sweep, W2: this loop kept the previous size's child in
    its frame, and a size's graph depended on which other sizes the command asked for)."""
    from stiefelsym.ir.seal import import_engine
    _die_with_parent()
    _not_dumpable("the second phase's process")
    import_engine()                     # once, before the forks: each child imports the file itself
    _flush()
    loop = os.fork()
    if loop == 0:
        code = 1
        try:
            _size_loop(path, requests, answer, timeout, memory)
            code = 0
        finally:
            os._exit(code)
    os.waitpid(loop, 0)


def _size_loop(path: str, requests: int, answer: int, timeout: float, memory: int | None) -> None:
    import ctypes
    _die_with_parent()
    fork = ctypes.PyDLL(None).fork
    fork.restype, fork.argtypes = None, []
    me = os.getpid()
    signal.signal(signal.SIGCHLD, signal.SIG_IGN)
    while True:
        byte = last = b""       # (nothing of the previous size's end in this frame when the next child is forked)
        with _Between():        # a process one size's child left ends with it: the next size's sees none
            r, w = os.pipe()
            fork()
            if os.getpid() != me:
                os.close(r)
                signal.signal(signal.SIGCHLD, signal.SIG_DFL)
                _size_child(path, requests, answer, timeout, memory, w)     # (never returns)
            os.close(w)
            last = b""
            while True:
                byte = os.read(r, 1)
                if not byte:
                    break
                last = byte
            os.close(r)
        if last == b"n":
            return


def _size_child(path: str, requests: int, answer: int, timeout: float, memory: int | None, done: int) -> None:
    """One child of the second phase (:func:`_size_loop`): it reads its request, traces the size in a process of its
    own (which it reaps, and reports when it ended without an answer), writes one byte on ``done`` (``n``: no request
    was left) and ends."""
    end = b"d"
    try:
        line = b""
        while not line.endswith(b"\n"):
            byte = os.read(requests, 1)      # one line only: the next is the next child's
            if not byte:
                break
            line += byte
        os.close(requests)
        if not line.strip():
            end = b"n"
        else:
            worker = os.fork()
            if worker == 0:
                code = 1
                try:
                    os.close(done)
                    data = _tracer(path, json.loads(line), timeout, memory,
                                   lambda marker: write_fully(answer, marker)) + b"\n"
                    write_fully(answer, data)
                    code = 0
                finally:
                    _flush()
                    os._exit(code)
            _, status = os.waitpid(worker, 0)
            if not (os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0):
                _kill_tree_of(worker)
                how = "killed" if os.WIFSIGNALED(status) else f"exit status {os.WEXITSTATUS(status)}"
                data = json.dumps({"error": f"the tracing at one size ended without a result ({how})"}).encode()
                os.write(answer, b"\n" + data + b"\n")
    finally:
        try:
            os.write(done, end)
        finally:
            _flush()
            os._exit(0)


class _Between:
    """Between two jobs of a claims file's interpreter (the import and each claim's grandchild, each size's child of
    the second phase): every process the job started is ended when it is (:class:`stiefelsym.run.confine.Confined`:
    a subreaper, so that a double fork or ``setsid`` does not escape), and, confined in namespaces, the System V
    IPC objects of the interpreter's own IPC namespace are removed.  With the read-only file system
    (:func:`stiefelsym.run.sandbox.lock_down`) nothing a job saw reaches the next one: what a claim traces at a size
    depends on the file and that size alone, not on which claims or sizes were traced before it."""

    def __enter__(self) -> "_Between":
        from stiefelsym.run.confine import Confined
        self.confined = Confined().__enter__()
        return self

    def __exit__(self, *exc: Any) -> None:
        try:
            self.confined.__exit__(*exc)
        finally:
            from stiefelsym.run import sandbox
            if sandbox.CONFINED:
                _clear_ipc()


def _clear_ipc() -> None:
    """Remove every System V shared memory segment, semaphore set and message queue this IPC namespace holds (the
    interpreter's own: ``unshare --ipc``)."""
    import ctypes
    libc = ctypes.CDLL(None, use_errno=True)
    for kind, remove in (("shm", lambda i: libc.shmctl(i, 0, None)), ("sem", lambda i: libc.semctl(i, 0, 0)),
                         ("msg", lambda i: libc.msgctl(i, 0, None))):
        try:
            with open(f"/proc/sysvipc/{kind}") as fh:
                rows = fh.read().splitlines()[1:]
        except OSError:
            continue
        for row in rows:
            fields = row.split()
            if len(fields) > 1 and fields[1].isdigit():
                remove(int(fields[1]))      # IPC_RMID = 0


def _kill_tree_of(pid: int) -> None:
    """(the process group a dead child of the second phase left: its own tracer's children)"""
    try:
        os.killpg(pid, signal.SIGKILL)
    except OSError:
        pass


def _flush() -> None:
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except BaseException:   # noqa: BLE001 - a stream the file replaced or closed
            pass


# --------------------------------------------------------------------------- the verifying process

class _Recorded:
    """A refusal recorded in a child: raised again with the same class name and message, from the
    claim's file and line (so that a run's message reads as it does when the claim is traced here)."""

    __slots__ = ("name", "message", "at")

    def __init__(self, data: Any) -> None:
        err = _get(data, "error", list)
        if len(err) != 2 or not all(type(x) is str for x in err) or not err[0].isidentifier():
            raise WireError("a refusal that is not (class name, message)")
        self.name, self.message = err
        at = _get(data, "at", list, optional=True)
        if at is not None and (len(at) != 2 or type(at[0]) is not str or type(at[1]) is not int or at[1] < 1):
            raise WireError("a refusal's place that is not (file, line)")
        self.at = at

    def exception(self) -> BaseException:
        from stiefelsym.ir import NotDeterministic, TraceRefused
        from stiefelsym.ir.replay import ReplayError
        known = {"TraceRefused": TraceRefused, "NotDeterministic": NotDeterministic, "ReplayError": ReplayError,
                 "ClaimTimeout": ClaimTimeout, "NoGraph": NoGraph}
        base = known.get(self.name)
        if base is None:
            b = getattr(builtins, self.name, None)
            base = b if isinstance(b, type) and issubclass(b, Exception) else Exception
        message = self.message
        if base is MemoryError:
            # raised while the claim was traced in its child (by the claim's code, or the tracing ran out of that
            # process's address space): not a method's memory budget
            base, message = Exception, f"MemoryError while the claim was traced in its claims file's child process: {message}"
        for cls in (base, Exception):
            try:
                kind = type(self.name, (cls,), {"__str__": lambda self: message, "__module__": cls.__module__})
                exc = kind(message)
                break
            except TypeError:
                continue
        return exc

    def throw(self) -> None:
        exc = self.exception()
        if self.at is None:
            raise exc
        path, line = self.at
        # the place as the file's code named it (a code object can be given any file name): said so in messages
        exc._recorded_at = (path, line)   # type: ignore[attr-defined]
        code = compile("\n" * (min(line, 10 ** 6) - 1) + "raise __recorded", path, "exec")
        exec(code, {"__recorded": exc})


class _Budget:
    """A trace that did not finish in the child: it ran out of the tracing time budget (:data:`CLAIM_SECONDS`), or its process died.
    Replayed as an exception (:class:`TraceEnded`) in whatever process asks for the graph: never as the
    process's own end (a replay that exited or killed itself would let the file choose the exit status of
    ``check`` or ``derive``, which run it in their own process), so the run's verdict is ``inconclusive`` (out of
    time) or ``error``."""

    __slots__ = ("what", "how", "after", "skipped")

    def __init__(self, data: dict) -> None:
        self.what = _get(data, "budget", str)
        self.how = _get(data, "how", str, optional=True) or ""
        if self.what not in ("timeout", "died"):
            raise WireError(f"an unknown budget outcome {self.what!r}")
        # a key not traced because the function ran out of time at an earlier one ("symbolic" or (n, r), r = k)
        after = _get(data, "after", str, list, optional=True)
        if after is not None and after != "symbolic" and not (
                type(after) is list and len(after) == 2 and type(after[1]) is int
                and (type(after[0]) is int or after[0] == "r")):
            raise WireError("a budget's earlier key that is not 'symbolic', (n, r) or a family (\"r\", k)")
        self.skipped = after is not None
        self.after = None if after is None or after == "symbolic" else tuple(after)
        if self.skipped and self.what != "timeout":
            raise WireError("a key left untraced after an outcome that is not a timeout")

    def throw(self, where: str = "") -> None:
        raise TraceEnded(self.text(where), timeout=self.what == "timeout")

    def text(self, where: str = "") -> str:
        """What happened, ``where`` (" at (3,2)", " with symbolic sizes"): the limit and whether it can be raised
        (the verifying process's own :data:`CLAIM_SECONDS`, not a number the child sent)."""
        if self.skipped:
            first = f"its tracing{_where(self.after)}"
            return (f"exceeded its time budget before it was traced{where}: {first} in its claims file's child "
                    f"process had run out of the engine's tracing budget of {CLAIM_SECONDS:.0f} s per function and "
                    "size, and a function that runs out of it is not traced again (the budget is not --timeout "
                    "and is the same in every run; see the guide, 'A claims file')")
        if self.what == "timeout":
            return (f"exceeded its time budget while its claims file's child process traced it{where}: the tracing "
                    f"(the claim's code, run twice and compared) did not finish within the engine's tracing budget "
                    f"of {CLAIM_SECONDS:.0f} s per function and size, which is not --timeout and is the same in "
                    "every run (see the guide, 'A claims file'): make the claim's code cheaper at that size")
        return (f"the tracing of the claim ended without a result ({self.how or 'its process died'}){where} in its "
                f"claims file's child process (whose address space is limited to {CLAIM_MEMORY_GIB:g} GiB)")


def _where(key: Any) -> str:
    if key is None:
        return " with symbolic sizes"
    if key[0] == "r":
        return f" on the family r = {key[1]}"
    return f" at ({key[0]},{key[1]})"


def _graph(data: Any) -> Any:
    from stiefelsym.ir import Graph
    ops = _get(data, "ops", list)
    args = [_value(a) for a in _get(data, "args", list)]
    if not all(type(o) is str for o in ops) or not all(type(a) is tuple for a in args):
        raise WireError("a graph whose ops are not strings or whose arguments are not tuples")
    sizes = _get(data, "sizes", list, optional=True)
    if sizes is not None and (len(sizes) != 2 or not all(type(x) is int for x in sizes)):
        raise WireError("a graph's size that is not (n, r)")
    fns = _get(data, "fns", int)
    g = Graph()
    g.__setstate__((ops, args, _value(_get(data, "output", dict)), [], fns, None if sizes is None else tuple(sizes)))
    return g


class TracedFunction:
    """A claim's function (or a correction's) as traced in the claims file's child: called by the
    engine's tracer, it replays the graph traced at the trace's size (:class:`~stiefelsym.ir.replay.GraphClaim`),
    raises the refusal recorded there, or raises :class:`NoGraph`.  No code of the file runs here."""

    def __init__(self, name: str, realization: str, entries: list, path: str, line: int,
                 confinement: str = "namespaces") -> None:
        from stiefelsym.ir.replay import GraphClaim
        from stiefelsym.run.sandbox import note
        # the engine's steps and constants the graphs name (stiefelsym.twisted.at_point, ...) are registered by
        # their modules, which the replay imports where this process has not (stiefelsym.ir.replay._registered)
        self._replay: Callable[..., Any]
        self.__name__ = self.__qualname__ = name
        self.realization, self.path, self.line = realization, path, line
        #: the file this process loaded (set by :func:`_claim`; ``path`` is what the file's code says of itself)
        self.loaded_from: str | None = None
        #: how the file was confined while traced (stiefelsym.run.sandbox), and what its records say of it
        self.confinement = confinement
        self.confinement_note = note(confinement)
        self._table: dict[Any, Any] = {}
        for entry in entries:
            if type(entry) is not list or len(entry) != 2:
                raise WireError("a graph entry that is not (size, graph)")
            key, data = entry
            if key is not None:
                if type(key) is not list or len(key) != 2 or not (
                        all(type(x) is int for x in key) or (key[0] == "r" and type(key[1]) is int and key[1] >= 1)):
                    raise WireError("a graph's key that is not (n, r) or a family (\"r\", k)")
                key = tuple(key)
            if type(data) is not dict:
                raise WireError("a graph entry that is not a mapping")
            if "budget" in data:
                self._table[key] = _Budget(data)
            else:
                self._table[key] = _Recorded(data) if "error" in data else data   # a graph: decoded when asked
        self._replay = GraphClaim

    def sizes(self) -> list:
        return sorted(k for k in self._table if k is not None and k[0] != "r")

    def symbolic(self) -> bool:
        """Whether the file's child traced a graph with symbolic sizes (which serves every size) rather than a
        refusal there: then no size of a run needs a graph of its own."""
        return None in self._table and type(self._table[None]) not in (_Budget, _Recorded)

    def __call__(self, s: Any) -> Any:
        from stiefelsym.ir.graph import Size as GSize
        from stiefelsym.ir.trace import _ACTIVE
        if not _ACTIVE:
            raise NoGraph(f"{self.__name__} is a traced claim: only the engine's tracer calls it")
        t = _ACTIVE[-1]
        n, r = t._numbers(GSize(1, "n", None)), t._numbers(GSize(1, "r", None))
        key = None if n is None else (n, r)
        family = t._family
        if key is None and family is not None and family.one_of_every_r and ("r", family.r) in self._table:
            # traced on the family r = k (every n >= k: it holds on any later start) of a claim stated at every r,
            # for a proof at a size only (:func:`stiefelsym.methods.specialise.specialised` compares it with the
            # graph at that size); a claim stated at r = k alone is proved on its family for every n, with the
            # graph its child traced with symbolic sizes, as before
            key = ("r", family.r)
        if t.constraints[0] != self.realization:
            raise NoGraph(f"{self.__name__} was traced in the {self.realization} realization only, "
                          f"not in the {t.constraints[0]} one")
        entry = self._table.get(key)
        if entry is None and key is not None and type(self._table.get(None)) is dict:
            # traced with symbolic sizes, which serves every size, so not at this one: that graph was refused here
            # (a replay that failed leaves its data in the table), and the refusal is the reason, not the sizes
            try:
                self._replay(_graph(self._table[None]), name=self.__name__)
                why = ""
            except Exception as exc:        # noqa: BLE001 (the replay's refusal, whatever its type, is the reason)
                why = f": {type(exc).__name__}: {exc}"
            raise NoGraph(f"{self.__name__} has no graph at ({n},{r}): its claims file's child traced it with "
                          f"symbolic sizes (a graph that serves every size), and that graph was refused here{why}")
        if entry is None:
            where = "with symbolic sizes" if key is None else f"at ({n},{r})"
            have = ", ".join(f"({a},{b})" for a, b in self.sizes()) or "none"
            raise NoGraph(f"{self.__name__} has no graph {where}: its claims file was traced in a child process "
                          f"at the sizes the run needed only ({have})")
        if type(entry) is _Budget:
            entry.throw(_where(key))
        if type(entry) is _Recorded:
            entry.throw()
        if type(entry) is dict:
            entry = self._table[key] = self._replay(_graph(entry), name=self.__name__)
        return entry(s)

    def budgets(self) -> list[str]:
        """What ran out of a tracing budget (:meth:`_Budget.text`), one text per outcome with every key it was
        met at (a function out of time with symbolic sizes is not traced at its sizes either), for the note on
        standard error."""
        keys: dict[tuple, list] = {}
        for k, e in self._table.items():
            if type(e) is _Budget:
                keys.setdefault((e.what, e.how, e.skipped, e.after), []).append((k, e))
        out = []
        for ks in keys.values():
            shown = [_where(k).strip() for k, _ in ks[:4]] + ([f"{len(ks) - 4} more"] if len(ks) > 4 else [])
            out.append(ks[0][1].text(" " + ", ".join(shown)))
        return out

    def __repr__(self) -> str:
        return f"<traced claim function {self.__name__}>"

    def __reduce__(self):
        raise TypeError("a traced claim function is not pickled")


class _Lookup:
    """A metadata callable of the claim as a table computed in its child (a size outside it: an error)."""

    def __init__(self, what: str, rows: Any) -> None:
        self.what = what
        self.bounds_only = False
        self.table: dict[tuple[int, int], Any] = {}
        if type(rows) is not list:
            raise WireError(f"the {what} table is not a list")
        for row in rows:
            if type(row) is not list or len(row) != 3 or type(row[0]) is not int or type(row[1]) is not int:
                raise WireError(f"a row of the {what} table that is not (n, r, value)")
            v = row[2]
            self.table[(row[0], row[1])] = v if type(v) is bool else _Recorded(v)

    def __call__(self, n: int, r: int) -> bool:
        v = self.table.get((n, r))
        if v is None:
            raise NoGraph(f"the claim's {self.what} was evaluated in its claims file's child process at the sizes "
                          f"the run needed only, not at ({n},{r})")
        if type(v) is _Recorded:
            v.throw()
        return v


@dataclasses.dataclass(frozen=True)
class TabledSizes(SizeSpec):
    """A size statement rebuilt from a child's data: its fields as sent, and ``admits`` the child's own answer
    (the claim's ``admits``, whatever it overrides) at every size of the table; beyond the table, the fields'
    bounds when the statement has no further condition, else an error.  A statement that was a plain
    :class:`SizeSpec` in the child (``fields_first``: its admits() reads its declared fields before its
    condition) admits here only what its fields admit, whatever the table says: its declared r (r_min = r_max,
    r_is_n) holds at every size it admits, by construction."""

    fields_first: bool = False

    def admits(self, n: int, r: int) -> bool:
        if self.fields_first and not SizeSpec.admits(dataclasses.replace(self, where=None), n, r):
            return False
        table = getattr(self.where, "table", None)
        if table is not None and (n, r) in table:
            return bool(self.where(n, r))                   # type: ignore[misc]
        if self.where is not None and not getattr(self.where, "bounds_only", False):
            return bool(self.where(n, r))                   # raises: a size outside the table
        return SizeSpec.admits(dataclasses.replace(self, where=None), n, r)

    def describe(self) -> str:
        plain = getattr(self.where, "bounds_only", False)
        return SizeSpec.describe(dataclasses.replace(self, where=None) if plain else self)


def _opt_int(d: dict, key: str) -> int | None:
    return _get(d, key, int, optional=True)


def _claim(d: Any, path: str, confinement: str = "namespaces") -> Claim:
    spec_d = _get(d, "sizes", dict)
    pairs = _get(spec_d, "list", list)
    if not all(type(p) is list and len(p) == 2 and all(type(x) is int for x in p) for p in pairs):
        raise WireError("a size that is not (n, r)")
    r_in = _get(spec_d, "r_in", list, optional=True) or []
    if any(not (v == "n" or (type(v) is int and v >= 1)) for v in r_in) or len(set(r_in)) != len(r_in):
        raise WireError("a size statement's r_in that is not distinct values r = k >= 1 and 'n'")
    admits = _Lookup("size condition", _get(spec_d, "admits", list))
    admits.bounds_only = not _get(spec_d, "where", bool)
    spec = TabledSizes(tuple(Size(n, r) for n, r in pairs), n_min=_get(spec_d, "n_min", int),
                       r_min=_get(spec_d, "r_min", int), r_max=_opt_int(spec_d, "r_max"),
                       where=admits,
                       condition=_get(spec_d, "condition", str), n_max=_opt_int(spec_d, "n_max"),
                       r_is_n=_get(spec_d, "r_is_n", bool), r_in=tuple(r_in),
                       fields_first=_get(spec_d, "fields_first", bool))
    realization = _get(d, "realization", str)
    src_path, line, name = _get(d, "path", str), _get(d, "line", int), _get(d, "name", str)
    fails = _get(d, "fails_at", list, optional=True)
    corrections = []
    for k in _get(d, "corrections", list):
        desc = _get(k, "description", str)
        if not desc.strip() or any(c.description == desc for c in corrections):
            raise WireError(f"two corrections described {desc!r}, or an empty description (the description names "
                            "the correction in the records)")
        corrections.append(Correction(desc, TracedFunction(f"{name} ({desc})", realization, _get(k, "graphs", list),
                                                           src_path, line, confinement),
                                      _get(k, "changes", int), _get(k, "expect", str, optional=True),
                                      _exact_pairs(_get(k, "exact_max_r", list)),
                                      _exact_pairs(_get(k, "exact_corank", list, optional=True) or [])))
    paper = _get(d, "paper", list)
    if not all(type(p) is str for p in paper):
        raise WireError("a paper label that is not a string")
    c = Claim(id=_get(d, "id", str), paper=tuple(paper), kind=_get(d, "kind", str),
              section=_get(d, "section", str),
              func=TracedFunction(name, realization, _get(d, "graphs", list), src_path, line, confinement),
              sizes=spec, statement=_get(d, "statement", str), title=_get(d, "title", str),
              realization=realization, expect=_get(d, "expect", str), exact_max_n=_get(d, "exact_max_n", int),
              exact_max_r=_exact_pairs(_get(d, "exact_max_r", list)),
              exact_corank=_exact_pairs(_get(d, "exact_corank", list, optional=True) or []),
              free_max_r=_get(d, "free_max_r", int, optional=True) or 0,
              corrections=corrections, source=_get(d, "source", str),
              fails_at=None if fails is None else _Lookup("erratum sizes (fails_at)", fails),
              erratum=_get(d, "erratum", str), place=_get(d, "place", str, optional=True) or "",
              slips=_slips(_get(d, "slips", list, optional=True) or []),
              equivariance=_get(d, "equivariance", str))
    for f in [c.func] + [k.func for k in corrections]:
        f.loaded_from = path             # the file this process loaded (not what the file's code says of itself)
    for k in range(len(corrections)):
        try:
            c.corrected(k)               # a correction's symbolic budget is validated as the claim's
        except ValueError as exc:
            raise WireError(str(exc)) from None
    return c


def _preload() -> dict[str, str]:
    """Before a file's interpreter is spawned without namespaces (it writes with the user's rights there): every
    module of the engine imported here (the child seals the verdict modules before the file runs; this process
    evaluates, renders and writes with the whole package afterwards, and reads none of it from disk once such a
    child has run), then :func:`_digests`.  In namespaces the file writes nowhere on the host's file system
    (:func:`stiefelsym.run.sandbox.lock_down`: every mount read-only), so nothing is imported first there (the
    package, scipy among what it imports, takes about a second), and the digests are compared all the same."""
    from stiefelsym.run.confine import import_package
    from stiefelsym.ir.seal import import_engine
    import_engine()
    import_package()
    return _digests()


def _digests() -> dict[str, str]:
    """The digest of every file of the package (:func:`stiefelsym.run.confine.engine_files`) and of every top-level
    module on the import path (:func:`stiefelsym.run.confine.path_modules`: a lazily imported library's name put
    before it), compared when the file's interpreter returns."""
    from stiefelsym.run.confine import engine_files, path_modules
    return {**engine_files(), **path_modules()}


def _engine_unchanged(before: dict[str, str], path: Path) -> None:
    """Raise :class:`CatalogError` when a file of the package, or a top-level module on the import path, changed
    while the claims file's child ran."""
    from stiefelsym.run.confine import changed_files, engine_files, path_modules
    engine, modules = engine_files(), path_modules()
    changed = changed_files(before, {**engine, **modules})
    if changed:
        shown = ", ".join(changed[:5]) + (f" and {len(changed) - 5} more" if len(changed) > 5 else "")
        folder = Path(path).resolve().parent
        if any(Path(p).resolve().parent == folder for p in changed):
            where = "a module in the claims file's own folder (which is on the import path)"
        elif all(p in engine for p in changed):
            where = "the engine's files"
        else:
            where = "the engine's files or the modules on its import path"
        raise CatalogError(f"{path}: {where} changed on disk while "
                           f"the claims file ran ({shown}), by the file or by another process (a package being edited "
                           "or reinstalled meanwhile): no verdict is given, and later runs would use the changed code: "
                           "if the change is not yours, restore the package (e.g. git checkout, or reinstall it) and "
                           "remove the files the claims file added before running again")


def _phase(path: Path, parts: list[dict] | None, capture: int,
           before_plain: Callable[[], None] | None = None) -> tuple[list, str]:
    """One phase in a fresh interpreter (:func:`stiefelsym.run.sandbox.run`): its decoded answer (per part, for the
    second phase), and the confinement it ran under.  It is given the file and the engine's tracing budgets
    (:data:`CLAIM_SECONDS`, :data:`CLAIM_MEMORY_GIB`), nothing of the run; in the second phase the ``parts``
    (one per size, :func:`_by_size`), one line each on a pipe that each of its children reads one line of
    (:func:`_tracer_by_size`), its answer one line per part."""
    from stiefelsym.run.sandbox import run
    real = os.path.realpath(path)      # what the interpreter opens (a link or a relative path may not be in its view)
    config = {"file": real, "second": parts is not None, "timeout": CLAIM_SECONDS,
              "memory": int(CLAIM_MEMORY_GIB * GIB)}
    requests = b"".join(json.dumps(m).encode() + b"\n" for m in parts or [])
    try:
        from stiefelsym.claims import IMPORT_SECONDS
        data, how = run(config, capture, FILE_SECONDS, requests, before_plain,
                        IMPORT_SECONDS + IMPORT_GRACE_SECONDS + IMPORT_START_SECONDS,
                        max(CLAIM_SECONDS, META_SECONDS) + BEAT_GRACE_SECONDS)
    except ProcessesLeft as exc:
        raise CatalogError(f"{path}: {exc}") from None
    if data is None:
        raise CatalogError(f"{path}: loading and tracing the file ended without a result (its process died, its "
                           f"import outlived {IMPORT_SECONDS:.0f} s, its tracing stopped making progress for "
                           f"{max(CLAIM_SECONDS, META_SECONDS) + BEAT_GRACE_SECONDS:.0f} s, or the whole took more than "
                           f"{FILE_SECONDS:.0f} s)")
    answers = [_loads(data)] if parts is None else [_loads(x) for x in data.split(b"\n") if x.strip()]
    if parts is not None and len(answers) != len(parts):
        raise WireError("a second phase's answer that is not one per size")
    out = []
    for answer in answers:
        if type(answer) is dict and "error" in answer:
            raise CatalogError(_get(answer, "error", str).replace(real, str(path)))   # the path as the user gave it
        items = _get(answer, "claims", list)
        for item in items:
            if type(item) is dict and "failed" in item:
                failed = _get(item, "failed", list)
                if len(failed) != 2 or not all(type(x) is str for x in failed):
                    raise WireError("a failure that is not (claim, message)")
                raise CatalogError(f"{path}: claim {failed[0]}: {failed[1]}")
        out.append([_get(item, "claim", dict) for item in items])
    return out, how


def _not_deterministic(data: Any) -> bool:
    """Whether a recorded refusal says that the function is not deterministic."""
    err = data.get("error") if type(data) is dict else None
    return type(err) is list and len(err) == 2 and err[0] == "NotDeterministic"


def _refused(entries: list) -> bool:
    """Whether a function's graphs hold no graph with symbolic sizes (refused there, or its process died; not a
    function found not deterministic there, which is traced at no size)."""
    for entry in entries:
        if type(entry) is list and len(entry) == 2 and entry[0] is None:
            data = entry[1]
            return (type(data) is dict and ("error" in data or data.get("budget") == "died")
                    and not _not_deterministic(data))
    return False


def _second_phase(claims: list, needed: list[tuple[int, int]]) -> dict:
    """What the second phase is asked, per claim id (see :func:`_claim_more`): the needed sizes beyond the
    first phase's tables (when the claim's answer there depends on the file), and, for the functions that have no graph with symbolic sizes, the needed sizes they
    are traced at (admitted, not listed: the listed ones were traced in the first phase)."""
    more: dict = {}
    for d in claims:
        spec = _get(d, "sizes", dict)
        rows = {(row[0], row[1]): row[2] for row in _get(spec, "admits", list)
                if type(row) is list and len(row) == 3}
        listed = {tuple(p) for p in _get(spec, "list", list) if type(p) is list}
        funcs = [f for f, entries in enumerate([_get(d, "graphs", list)] + [_get(k, "graphs", list) for k in
                                                                           _get(d, "corrections", list)])
                 if _refused(entries)]
        # beyond the tables: asked only where an answer depends on the file (a condition of its own, erratum
        # sizes, a function traced per size); a statement of bounds only is decided here by its bounds
        tabled = _get(spec, "where", bool) or d.get("fails_at") is not None or funcs
        table = [p for p in needed if p not in rows] if tabled else []
        trace = [p for p in needed if rows.get(p) is True and p not in listed] if funcs else []
        if table or trace:
            more[_get(d, "id", str)] = {"table": [list(p) for p in table], "trace": [list(p) for p in trace],
                                         "funcs": funcs}
    return more


def _by_size(more: dict) -> list[dict]:
    """The second phase (:func:`_second_phase`) split by size: one child of its interpreter per size, asked at that size
    only (and, confined in namespaces, with nothing left by the child of another size: :class:`_Between`),
    so that a function traced there, or a size condition evaluated there, sees no other size of the run (what
    it is asked at a size depends on the file and that size alone)."""
    sizes = sorted({(p[0], p[1]) for m in more.values() for p in m["table"] + m["trace"]})
    out = []
    for z in sizes:
        part = {}
        for cid, m in more.items():
            table, trace = [list(z)] if list(z) in m["table"] else [], [list(z)] if list(z) in m["trace"] else []
            if table or trace:
                part[cid] = {"table": table, "trace": trace, "funcs": m["funcs"]}
        out.append(part)
    return out


def _merge(claims: list, extra: list, more: dict) -> None:
    """The second phase's rows and graphs added to the first phase's claims (never replacing one of them)."""
    by_id = {d["id"]: d for d in claims}
    for e in extra:
        cid = _get(e, "id", str)
        if cid not in more or cid not in by_id:
            raise WireError(f"the second phase answered for a claim it was not asked about ({cid!r})")
        d = by_id[cid]
        spec = d["sizes"]
        asked = {tuple(p) for p in more[cid]["table"]}
        known = {(row[0], row[1]) for row in spec["admits"]}
        for row in _get(e, "admits", list):
            if type(row) is list and len(row) == 3 and (row[0], row[1]) in asked - known:
                spec["admits"].append(row)
        fails = _get(e, "fails_at", list, optional=True)
        if d.get("fails_at") is not None and fails is not None:
            have = {(row[0], row[1]) for row in d["fails_at"]}
            d["fails_at"] += [row for row in fails if type(row) is list and len(row) == 3
                              and (row[0], row[1]) in asked - have]
        graphs = [d["graphs"]] + [k["graphs"] for k in d["corrections"]]
        funcs = set(more[cid]["funcs"])
        for res in _get(e, "results", list):
            if type(res) is not list or len(res) != 3 or type(res[0]) is not int or res[0] not in funcs \
                    or res[1] is None:
                raise WireError("a second phase's graph that is not (function, size, graph)")
            f, key, entry = res
            if any(type(g) is list and len(g) == 2 and g[0] == key for g in graphs[f]):
                continue
            graphs[f].append([key, entry])


def load_claims_isolated(path: str | Path, sizes: Iterable[Any] = (), only: Iterable[str] | None = None) -> Registry:
    """The claims of a user's file, imported and traced in fresh interpreters (see the module docstring),
    at their listed sizes and at ``sizes`` (Size or (n, r)) where they admit them; each trace has the engine's
    budgets (:data:`CLAIM_SECONDS`, :data:`CLAIM_MEMORY_GIB`), the same in every run.  ``only``: the ids of the
    claims the run names (None: all of them); the others are not traced at ``sizes``, which they are not run at
    (a size of 200 asked for one claim traced the file's other claims there first).  Raises
    :class:`~stiefelsym.claims.CatalogError` as :func:`~stiefelsym.claims.load_claims_file` does."""
    if not (hasattr(os, "fork") and hasattr(os, "posix_spawn")):
        return load_claims_file(path)
    needed = []
    for s in sizes:
        n, r = (s.n, s.r) if isinstance(s, Size) else tuple(s)
        if type(n) is int and type(r) is int and 1 <= r <= n:
            needed.append((n, r))
    needed = list(dict.fromkeys(needed))
    p = Path(path)
    if not p.is_file():
        raise CatalogError(claims_file_missing(p))
    engine = _digests()
    spawned: list[bool] = []

    def before_plain() -> None:
        """(before the first interpreter without namespaces, when no interpreter of the file has run yet: the
        package imported, and the digests taken again since importing may write its byte code)"""
        nonlocal engine
        if not spawned:
            engine = _preload()
        # without a PID namespace the file's processes can name this one (its parent's parent): no process of the
        # same user reads or writes its memory (process_vm_writev, ptrace) once it is not dumpable (for the rest of
        # its life: a debugger attaches before the file is loaded, or runs as root)
        _not_dumpable("the verifying process")

    sys.stdout.flush()
    sys.stderr.flush()
    with tempfile.TemporaryFile() as capture:
        try:
            (claims,), how = _phase(p, None, capture.fileno(), before_plain)     # no size of the run
            spawned.append(True)
            more = _second_phase(claims, needed)
            if only is not None:
                wanted = set(only)
                more = {k: v for k, v in more.items() if k in wanted}
            parts = _by_size(more)         # only what needs a size, one size each
            if parts:
                extras, how2 = _phase(p, parts, capture.fileno(), before_plain)
                for part, extra in zip(parts, extras):
                    _merge(claims, extra, part)
                how = how if how2 == how else f"{how}, then {how2}"
        except (WireError, ValueError, TypeError, RecursionError) as exc:
            if isinstance(exc, CatalogError):
                raise
            raise CatalogError(f"{p}: {exc}") from None
        finally:
            capture.seek(0)
            printed = capture.read(CAPTURE_BYTES)
            if printed:
                sys.stderr.write(printed.decode("utf-8", "replace"))
                sys.stderr.flush()
            _engine_unchanged(engine, p)
    try:
        reg = Registry()
        for d in claims:
            reg.add(_claim(d, str(p), how))
    except (WireError, ValueError, TypeError, RecursionError) as exc:
        if isinstance(exc, CatalogError):
            raise
        raise CatalogError(f"{p}: {exc}") from None
    if not len(reg):
        raise CatalogError(f"{p}: defines no claims (use the @claim decorator)")
    return reg
