"""Plans and runs verifications: claims x sizes x methods -> Result records.

Every (claim, size, method) of a plan runs in a forked worker process with a
wall-time budget and a memory budget (:mod:`stiefelsym.run.pool`); ``auto`` (exact,
then the dimension-free proof of the same graph, then modular) is budgeted as a whole.  A run that exceeds its time is
``inconclusive``; one that crashes, raises anything (``SystemExit`` included),
exhausts its memory or kills its process is an ``error``, and the plan goes on.
Whether a verdict is the expected one is decided here, in the parent process,
never by the code that ran the claim.
"""
from __future__ import annotations

import copy
import functools
import hashlib
import shlex
import time
from typing import Any, Callable, Iterable, Iterator, Sequence

from stiefelsym.claims import Claim, Registry, Size, statement_state
from stiefelsym.methods.hard import hard_case
from stiefelsym.methods.fixed_size import METHOD_RUNNERS, BudgetError, check_budget, expected_verdict, spaced_collections  # noqa: F401 (BudgetError is part of the runner API)
from stiefelsym.run.pool import DEFAULT_MEMORY_GIB, DEFAULT_TIMEOUT, GIB, MOST_GIB, MOST_SECONDS, Outcome, Terminated, WorkerPool, amount_problem  # noqa: F401
from stiefelsym.results import COPY_OF, PASSING, VERDICTS, Result
from stiefelsym.scene import SizeError
from stiefelsym.ir import numbers_only
from stiefelsym.ir import notation

METHODS = ("auto", "exact", "rational", "modular", "float", "ball", "free")
#: the verdicts that are never expected: the method could not decide, or the check broke
NEVER_EXPECTED = ("inconclusive", "error")

Task = tuple  # (claim index, n or None, r or None, method, correction index or -1)


def select(registry: Registry, ids: Iterable[str]) -> list[Claim]:
    """The claims named by ids (all claims when ids is empty)."""
    ids = list(ids)
    if not ids:
        return list(registry)
    return [registry.get(i) for i in ids]


def _sizes_for(claim: Claim, sizes: list[Size] | None) -> list[Size]:
    if sizes is None:
        return list(claim.sizes)
    return [s for s in sizes if claim.sizes.admits(s.n, s.r)]


def _spec_text(claim: Claim) -> str:
    describe = getattr(claim.sizes, "describe", None)
    return describe() if describe is not None else "its declared sizes"


def engine_methods(methods: Sequence[str], max_n: int | None) -> tuple[str, ...]:
    """The methods to plan: with --max-n, auto keeps its dimension-free run (which a plan with
    explicit sizes leaves out), in the same place as in a plan of the claims' own sizes."""
    if max_n is None:
        return tuple(methods)
    out: list[str] = []
    for m in methods:
        if m == "auto" and "free" not in methods:
            out.append("free")
        out.append(m)
    return tuple(out)


def sizes_without_claims(claims: list[Claim], sizes: Iterable[Size]) -> list[Size]:
    """The sizes that none of the claims is stated at (a run skips them; with no other size it is refused)."""
    return [s for s in sizes if not any(c.sizes.admits(s.n, s.r) for c in claims)]


def plan(claims: list[Claim], sizes: list[Size] | None, methods: Iterable[str],
         strict: bool = False) -> list[tuple[Claim, Size | None, str]]:
    """Every (claim, size, method) to run; size None is a dimension-free run.

    With ``strict`` (the claims were named explicitly) a size outside a claim's
    declared sizes is refused; otherwise such a claim skips that size, and so does
    every claim at a size that no claim admits, unless no size admits one: then the
    run is refused."""
    methods = list(methods)
    for m in methods:
        if m not in METHODS:
            raise ValueError(f"unknown method {m!r} (one of {', '.join(METHODS)})")
    if sizes is not None:
        for s in sizes:
            for m in methods:
                if m != "free":
                    check_budget(m, s.n, s.r)
        if any(m != "free" for m in methods):
            if strict:
                for c in claims:
                    for s in sizes:
                        if not c.sizes.admits(s.n, s.r):
                            raise SizeError(f"claim {c.id} is stated for sizes {_spec_text(c)}; "
                                            f"({s.n},{s.r}) is outside")
            empty = sizes_without_claims(claims, sizes)
            if empty and len(empty) == len(sizes):
                shown = ", ".join(f"({s.n},{s.r})" for s in empty)
                raise SizeError(f"no selected claim is stated for size{'s' if len(empty) > 1 else ''} {shown}")
    runs: list[tuple[Claim, Size | None, str]] = []
    for c in claims:
        for m in methods:
            if m == "free" or (m == "auto" and sizes is None):
                runs.append((c, None, "free"))
            if m == "free" or (m in ("float", "ball") and c.kind == "dim"):
                continue   # dimensions are integers: floating point has nothing to say about them
            for s in _sizes_for(c, sizes):
                runs.append((c, s, m))
    seen, out = set(), []
    for c, s, m in runs:
        key = (c.id, None if s is None else (s.n, s.r), m)
        if key not in seen:
            seen.add(key)
            out.append((c, s, m))
    return out


# --------------------------------------------------------------------------- one run

def run_one(claim: Claim, size: Size | None, method: str, seed: int, func: Callable | None = None,
            variant: str | None = None, hard: str | None = None, timeout: float | None = None) -> Result:
    """One result for one (claim, size, method), computed in this process (no budgets but the
    symbolic method's own, or those a run of ``timeout`` seconds gives it: ``check`` runs a record again
    under its file's budget); ``hard`` names a hard numerical case."""
    return _finish(_guarded(claim, size, method, seed, func, hard, timeout=timeout), claim, variant, hard)


def _guarded(claim: Claim, size: Size | None, method: str, seed: int, func: Callable | None,
             hard: str | None, in_worker: bool = False, timeout: float | None = None) -> Result:
    """The raw result (verdict policy not applied); whatever the claim raises is an ``error``.

    In a worker, MemoryError is left to the pool (which reports the memory budget and
    replaces the worker)."""
    from stiefelsym.methods.families import stated_on
    before = statement_state(claim)
    with stated_on(claim, func):
        res = _guarded_on(claim, size, method, seed, func, hard, in_worker, timeout)
    if statement_state(claim) != before:
        res = _error(claim, size, method, seed, "the claim changed its own statement (a field of the claim or of its "
                                                "statement of sizes) while it ran: no verdict is given")
    return res


def _guarded_on(claim: Claim, size: Size | None, method: str, seed: int, func: Callable | None,
                hard: str | None, in_worker: bool, timeout: float | None) -> Result:
    """:func:`_guarded`, with the claim's families of sizes stated."""
    options = {"hard": hard_case(hard)} if hard else None
    try:
        # the claim is traced before any method builds its scene or runs (the graph is cached for the
        # method): claim code never runs while a scene of a method is alive
        with spaced_collections():
            graph_digest(claim, size, func)
            shared = shared_size(claim, size, func) if method != "free" else None
        res = _dispatch(claim, shared or size, method, seed, func, options, in_worker, timeout)
        if shared is not None:
            res = _stated_shared(res, shared, size)
        if not res.digest:
            res.digest = graph_digest(claim, size, func)
        res.traced = traced_text(claim, size, func) if res.digest else []
        if res.certificate_data is not None:     # what the certificate is about (the standalone checker binds it)
            res.certificate_data = dict(res.certificate_data, about={"claim": claim.id, "digest": res.digest})
        return _confinement_stated(res, func or claim.func)
    except (KeyboardInterrupt, Terminated):
        raise
    except MemoryError:
        if in_worker:
            raise
        res = _error(claim, size, method, seed, "MemoryError: the computation ran out of memory")
    except BaseException as exc:  # noqa: BLE001 - a bug in the claim (or the engine), SystemExit included
        from stiefelsym.run.isolate import ChildError
        from stiefelsym.methods.fixed_size import _describe
        from stiefelsym.run.userfile import TraceEnded
        res = _error(claim, size, method, seed, str(exc) if isinstance(exc, ChildError) else _describe(exc))
        if isinstance(exc, TraceEnded) and exc.timeout:     # out of its time budget: undecided, not a bug
            res.verdict, res.message = "inconclusive", str(exc)
    # an error is bound to the graph it was met on like any verdict ("" when the claim does not trace)
    res.digest = _digest_or_none(claim, size, func)
    res.traced = traced_text(claim, size, func) if res.digest else []
    return _confinement_stated(res, func or claim.func)


def shared_size(claim: Claim, size: Size | None, func: Callable | None = None, screen: bool = False) -> Size | None:
    """The size (n, r0) whose run decides the run at ``size`` = (n, r), when the claim's graph involves no
    dimension r (:func:`stiefelsym.ir.passes.r_dependence`: no node of it has a side on ℝʳ, a size in r or a
    leaf built from a point of T*V) and is the same graph at (n, r) and (n, r0) (one graph with symbolic
    sizes, or the same graph traced at both sizes): its value at every point of T*V(n, r) is its value at the
    same A and parameters on T*V(n, r0), so the run at (n, r0) is the run at (n, r), and the records of every
    r at this n are one computation.  r0 is the least r the claim is stated for at n on which ``auto`` makes
    the same first attempt as at r (symbolic or not), so that the method is the same; it is a function of
    the claim and (n, r) alone, whatever else a plan holds, so that a run of (n, r) alone gives the record a
    run of the catalog gives.  None when the graph may depend on r (or does not trace: the run itself says
    why), and for a claim of a user's file that needs fixed sizes (its graphs at sizes are traced in
    another interpreter, on demand: not asked for here).

    ``screen`` (a plan, before it runs): a claim that needs fixed sizes is first looked at at its smallest
    size only, and not shared when its graph there involves r (so that a plan does not trace every claim at
    every size before it starts); that only leaves out sharing, never adds it: the run itself decides its
    record by the graphs at (n, r) and (n, r0)."""
    if size is None or claim.realization != "standard":
        return None
    from stiefelsym.methods.families import stated_on
    with stated_on(claim, func):
        return _shared_size(claim, size, func, screen)


def _shared_size(claim: Claim, size: Size, func: Callable | None, screen: bool) -> Size | None:
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.ir.passes import r_dependence
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[claim.realization]
    f = func or claim.func

    def graph(n: int | None, r: int | None):
        return compile_claim(f, n, r, (cons.name, cons.build))

    try:
        try:
            # symbolic sizes first: then the one graph is the claim's graph at every size
            first = graph(None, None)
        except Exception:   # noqa: BLE001 - needs fixed sizes: its graph at the claim's first size, below
            if type(f).__name__ == "TracedFunction":
                return None
            first = None
        if first is None:
            low = min(claim.sizes, key=lambda s: (s.n, s.r)) if screen else size
            first = graph(low.n, low.r)
        if r_dependence(first):
            return None
        exact = claim.exact_at(size.n, size.r)
        r0 = next(r for r in range(1, size.n + 1)
                  if claim.sizes.admits(size.n, r) and claim.exact_at(size.n, r) == exact)
        # the graph types at both sizes, and is the same graph there
        graphs = [graph(size.n, r) for r in dict.fromkeys((r0, size.r))]
        if any(r_dependence(g) or g.digest() != graphs[0].digest() for g in graphs):
            return None
    except Exception:   # noqa: BLE001 - a claim that does not trace (or a statement that raises): not shared
        return None
    return Size(size.n, r0)


def shared_note(shared: Size) -> str:
    """The reduction a record of a graph that involves no dimension r states (the same at every r it is
    shared by)."""
    n, r0 = shared.n, shared.r
    return (f"the graph at ({n}, r) is the graph at ({n},{r0}) and involves no dimension r (no leaf, size or "
            f"engine step of it depends on r): the result computed at ({n},{r0}) holds verbatim")


def _stated_shared(res: Result, shared: Size, size: Size) -> Result:
    """The result computed at ``shared`` as the result at ``size``, with the reduction stated."""
    note = shared_note(shared)
    if note not in res.reductions:
        res.reductions.append(note)
    return at_size(res, size.r)


def at_size(res: Result, r: int) -> Result:
    """A copy of ``res`` (a run at (n, r0) of a graph that involves no r) as the record at (n, r)."""
    if res.r == r:
        return res
    out = copy.deepcopy(res)
    out.r = r
    return out


def _confinement_stated(res: Result, func: Callable) -> Result:
    """A claims file traced with less than the full confinement (stiefelsym.run.sandbox) says so in every record."""
    note = getattr(func, "confinement_note", "") if type(func).__name__ == "TracedFunction" else ""
    if note and note not in res.reductions:
        res.reductions.append(note)
    return res


def run_free_guarded(claim: Claim, func: Callable | None = None) -> Result:
    """The dimension-free method in this process, whatever the claim raises an ``error`` (for ``derive`` and
    ``check``, which run it outside the pool): the raw result, its verdict policy not applied."""
    return _guarded(claim, None, "free", 0, func, None)


def _digest_or_none(claim: Claim, size: Size | None, func: Callable | None) -> str:
    """:func:`graph_digest`, "" when even asking for it raises (what a run that ended in error met)."""
    try:
        return graph_digest(claim, size, func)
    except (KeyboardInterrupt, Terminated):
        raise
    except BaseException:  # noqa: BLE001 - the error's message already says why
        return ""


def graph_digest(claim: Claim, size: Size | None, func: Callable | None = None) -> str:
    """The digest of the claim's graph at ``size`` (None: symbolic sizes), "" when it does not trace
    (traced once per process and size: a cache hit after the run).  With symbolic sizes, a claim stated at
    families of sizes (r = 1 and r = n, ...) that traces on each family but not on every size has the
    digest of its graphs on its families (those the dimension-free method proves it on)."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.methods.families import stated_on
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[claim.realization]
    try:
        with stated_on(claim, func):
            return compile_claim(func or claim.func, size.n if size else None, size.r if size else None,
                                 (cons.name, cons.build)).digest()
    except Exception:   # noqa: BLE001 - the run's verdict already says why the claim does not trace
        if size is not None:
            return ""
    from stiefelsym.methods.families import size_families
    try:
        families, _why = size_families(claim)
    except Exception:   # noqa: BLE001 - the statement's admits() raised: the run's verdict says it
        return ""
    if not families or None in families:
        return ""
    try:
        graphs = [(f, compile_claim(func or claim.func, None, None, (cons.name, cons.build), family=f).digest())
                  for f in families]
    except Exception:   # noqa: BLE001 - as above
        return ""
    return hashlib.sha256("\n".join(f"{f}: {d}" for f, d in graphs).encode()).hexdigest()


def traced_text(claim: Claim, size: Size | None, func: Callable | None = None,
                full: bool = False) -> list[list[str]]:
    """The claim's outputs as traced at ``size`` (None: symbolic sizes), in the paper's notation: one
    [name, Unicode, LaTeX] per output (:func:`stiefelsym.ir.notation.traced_outputs`), read from the graph
    the record's digest names; [] when the claim does not trace there.  A claim the dimension-free method
    takes on families of sizes has each family's outputs, named with the family.

    A record's text is cut to a reader's length: a long sum ends in "…", a matrix of many blocks is named
    by its shape, a graph of more than :data:`TRACED_NODES` nodes by its size.  ``full``: nothing is cut
    (every term, block and node read back; ``stiefelsym show --full``), never cached, never a record's."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.methods.families import size_families, stated_on
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[claim.realization]
    f = func or claim.func
    try:
        with stated_on(claim, func):
            try:
                graphs = [("", compile_claim(f, size.n if size else None, size.r if size else None,
                                             (cons.name, cons.build)))]
            except Exception:   # noqa: BLE001 - with symbolic sizes: perhaps on families (as graph_digest)
                if size is not None:
                    return []
                families, _why = size_families(claim)
                if not families or None in families:
                    return []
                graphs = [(str(fam), compile_claim(f, None, None, (cons.name, cons.build), family=fam))
                          for fam in families]
    except (KeyboardInterrupt, Terminated):
        raise
    except BaseException:   # noqa: BLE001 - the run's verdict says why the claim does not trace
        return []
    out: list[list[str]] = []
    for fam, g in graphs:
        text = [list(t) for t in notation.traced_outputs(g, notation.FULL_CAP)] if full else _record_text(g)
        out += [[f"{name} ({fam})" if fam else name, uni, tex] for name, uni, tex in text]
    return copy.deepcopy(out)


def _record_text(g: Any) -> list[list[str]]:
    """A record's text of the graph g (:func:`traced_text`): cut to a reader's length, cached by digest (the
    caller copies it)."""
    key = g.digest()
    text = _TRACED.get(key)
    if text is None and len(g.ops) > TRACED_NODES:
        # reading a graph back costs about 70 µs a node: one of tens of thousands (entries read one by one at
        # a large size) is named by its size only; the smallest size's graph is the one a report prints
        words = f"{notation.NOT_READ_BACK} {len(g.ops):,} nodes, not read back)"
        text = _TRACED[key] = [["", words, r"\text{" + words.replace(",", "{,}") + "}"]]
    if text is None:
        text = _TRACED[key] = [list(t) for t in notation.traced_outputs(g)]
        while len(_TRACED) > CHANGES_CACHE_SIZE:
            del _TRACED[next(iter(_TRACED))]
    return text


#: the outputs of a graph in the paper's notation (:func:`traced_text`), keyed by its digest
_TRACED: dict[str, list[list[str]]] = {}
#: a graph of more nodes than this is not read back (:func:`traced_text`); its text begins with
#: :data:`stiefelsym.ir.notation.NOT_READ_BACK`
TRACED_NODES = notation.TRACED_NODES


def graph_change(claim: Claim, func: Callable, size: Size | None) -> list[dict[str, str]]:
    """What ``func`` (a correction or a mutant of the claim) changes in the claim's graph, in the paper's
    notation (:func:`stiefelsym.ir.notation.diff`): one dict per change; both graphs traced with
    symbolic sizes when both trace so, else at ``size``.  [] when either does not trace, and one
    empty change (where = old = "") when the graphs compute the same outputs."""
    from stiefelsym.ir import graph_pair
    from stiefelsym.ir.notation import diff
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[claim.realization]
    try:
        pair = graph_pair(claim.func, func, size.n if size else None, size.r if size else None,
                          (cons.name, cons.build))
    except Exception:   # noqa: BLE001 - what does not trace has no notation; its runs say why
        return []
    if pair is None:
        return []
    # a registered correction may name the block matrix its change is made in
    blocks_of = next((c.blocks_of for c in claim.corrections if c.func is func), "")
    key = (pair[0].digest(), pair[1].digest(), blocks_of)
    text = _CHANGES.get(key)
    if text is None:
        changes = diff(*pair, blocks_of=blocks_of)
        text = _CHANGES[key] = [c.to_json() for c in changes] if changes else \
            [{"where": "", "old": "", "new": "", "old_tex": "", "new_tex": ""}]
        while len(_CHANGES) > CHANGES_CACHE_SIZE:
            del _CHANGES[next(iter(_CHANGES))]
    return copy.deepcopy(text)


#: the changes between two graphs (:func:`graph_change`), keyed by their digests: a function of the two
#: graphs, so a correction traced with symbolic sizes is read once for all the sizes it is run at
_CHANGES: dict[tuple[str, str], list[dict[str, str]]] = {}
CHANGES_CACHE_SIZE = 256


def _blank(claim: Claim, size: Size | None, method: str, seed: int | None) -> Result:
    from stiefelsym.methods.fixed_size import _base_result
    label = "free" if size is None else method
    return _base_result(claim, size.n if size else None, size.r if size else None, label,
                        None if label in ("exact", "free") else seed)


def _error(claim: Claim, size: Size | None, method: str, seed: int, message: str) -> Result:
    res = _blank(claim, size, method, seed)
    res.verdict, res.message = "error", message
    return res


def _exact_runner(in_worker: bool, budget: float | None, capped: bool = True) -> Callable[..., Result]:
    """The symbolic method: in a worker, a small attempt runs right there (the worker is the
    killable process) and a heavy one in its own forked child with the run's memory budget, so
    that the worker survives it (:func:`stiefelsym.methods.fixed_size.isolates`); elsewhere in its own
    killable child.  ``capped``: the attempt gets at most EXACT_TIME_LIMIT (auto's attempt, which the modular
    method follows); otherwise (``--method exact``) 0.7 of the run's budget: the rational point tried after an
    attempt that ran out ends by 4/3 of the attempt's budget, inside the run's.  Outside a worker (``check``
    running a record again with its file's budget), the same, in this process or a forked child."""
    if not in_worker and budget is None:
        return METHOD_RUNNERS["exact"]
    from stiefelsym.methods.fixed_size import EXACT_TIME_LIMIT, run_exact_isolated
    if budget is None:
        limit = EXACT_TIME_LIMIT
    else:
        limit = min(EXACT_TIME_LIMIT, budget) if capped else EXACT_SHARE * budget
    return lambda c, n, r, seed, func=None, options=None: run_exact_isolated(c, n, r, seed, func, limit,
                                                                             in_worker=in_worker)


#: the share of a run's budget (``--timeout``) that ``--method exact`` gives its symbolic attempt
EXACT_SHARE = 0.7


def _dispatch(claim: Claim, size: Size | None, method: str, seed: int, func: Callable | None,
              options: dict | None, in_worker: bool = False, timeout: float | None = None) -> Result:
    if method == "free" or size is None:
        from stiefelsym.methods.dimension_free import run_free
        from stiefelsym.methods.specialise import remember
        res = run_free(claim, func)
        remember(claim, func, res)      # the attempt a run of the claim at a size here would make: made
        return res
    if method == "auto":
        if options:
            return METHOD_RUNNERS["rational"](claim, size.n, size.r, seed, func, options)
        # the whole of auto shares one budget: the symbolic attempt gets half of it
        return _run_auto(claim, size, seed, func, _exact_runner(in_worker, None if timeout is None else timeout / 2),
                         timeout)
    if method == "exact":
        if options:
            raise ValueError("hard cases are sampled points: use --method rational, modular or float")
        return _run_exact(claim, size, seed, func, _exact_runner(in_worker, timeout, capped=False), timeout)
    return METHOD_RUNNERS[method](claim, size.n, size.r, seed, func, options)


def _specialised(claim: Claim, size: Size, seed: int, func: Callable | None, spent: float = 0.0,
                 budget: float | None = None) -> tuple[Result | None, float]:
    """The dimension-free proof of the graph the run at ``size`` evaluates, as the exact method's verdict there
    (:mod:`stiefelsym.methods.specialise`), or None; and the seconds the attempt took (a record's time is the
    whole run's: ``spent`` before it is added to a proof, the caller adds the attempt's to what it does next).
    ``budget``: the run's time budget (the dimension-free attempt gets a bounded part of it)."""
    from stiefelsym.methods.specialise import specialised
    t0 = time.perf_counter()
    res = specialised(claim, size.n, size.r, seed, func, budget)
    took = time.perf_counter() - t0
    if res is not None:
        res.seconds += spent
    return res, took


def _run_exact(claim: Claim, size: Size, seed: int, func: Callable | None, exact: Callable[..., Result],
               budget: float | None = None) -> Result:
    """The exact method: its symbolic charts within the claim's symbolic budget; beyond it, or where the
    charts end without a verdict, the dimension-free proof of the same graph where there is one."""
    if not claim.exact_at(size.n, size.r) and not numbers_only(claim, size.n, size.r, func):
        proof, took = _specialised(claim, size, seed, func, 0.0, budget)
        if proof is not None:
            return proof
        res = exact(claim, size.n, size.r, seed, func)
        res.seconds += took
        return res
    res = exact(claim, size.n, size.r, seed, func)
    if res.verdict == "inconclusive":
        proof, took = _specialised(claim, size, seed, func, res.seconds, budget)
        if proof is None:
            res.seconds += took
        return proof or res
    return res


def auto_budget_reason(claim: Claim, size: Size) -> str:
    """Why auto did not run the exact method at a size beyond the claim's symbolic budget (the first words of the
    message of the record of the method it ran instead, after "exact: ")."""
    return (f"({size.n},{size.r}) is above this claim's symbolic budget ({claim.exact_budget_text()})"
            if claim.exact_max_r or claim.exact_corank else
            f"n = {size.n} is above this claim's symbolic budget (n <= {claim.exact_max_n})")


#: from this n on, ``auto`` takes the dimension-free proof of the graph it evaluates first, where there is one (a
#: proof for every n, r specialised to the size, cross-checked by the modular method's points there), and runs
#: the exact method's own charts only where there is none: below it the exact charts stay an independent proof
#: of each such claim at every size (n <= 4: the catalog's exact runs of the claims the dimension-free method
#: proves took 27 s of 173 s of runs at n <= 4 and 47 s at n = 5, 6; the specialised proof takes milliseconds)
FREE_FIRST_N = 5


def _run_auto(claim: Claim, size: Size, seed: int, func: Callable | None,
              exact: Callable[..., Result] | None = None, budget: float | None = None) -> Result:
    exact = exact or METHOD_RUNNERS["exact"]
    tried_exact = claim.exact_at(size.n, size.r) or numbers_only(claim, size.n, size.r, func)
    spent, specialised_tried = 0.0, False
    if tried_exact and size.n >= FREE_FIRST_N:
        proof, spent = _specialised(claim, size, seed, func, 0.0, budget)
        if proof is not None:
            return proof
        specialised_tried = True
    if tried_exact:
        res = exact(claim, size.n, size.r, seed, func)
        res.seconds += spent
        if res.verdict != "inconclusive":
            return res
        reason = res.message
        spent = res.seconds
    else:
        reason = auto_budget_reason(claim, size)
    if not specialised_tried:
        proof, took = _specialised(claim, size, seed, func, spent, budget)
        if proof is not None:
            return proof
        spent += took
    res = METHOD_RUNNERS["modular"](claim, size.n, size.r, seed, func)
    res.message = "; ".join(m for m in (f"exact: {reason}" if reason else "", res.message) if m)
    res.seconds += spent
    if res.verdict in ("inconclusive", "undecided") and not tried_exact:
        # the points could not decide (a rank below the printed one at every point, say): the symbolic method
        # is tried after all, beyond the budget, within the run's time and memory budgets
        late = exact(claim, size.n, size.r, seed, func)
        late.seconds += res.seconds
        if late.verdict in ("proved", "fails"):
            late.message = f"{LATE_EXACT_PREFIX}{res.verdict}: {res.message}){LATE_EXACT_THEN}" + (
                f"; {late.message}" if late.message else "")
            return late
        res.message = f"{res.message}{LATE_MODULAR_MARK}{late.verdict} ({late.message})"
        res.seconds = late.seconds
    return res


#: how auto's record says that the exact method decided beyond the claim's symbolic budget after the modular
#: method could not (the record's method is exact), and how a modular record says what that attempt gave
LATE_EXACT_PREFIX = "the modular method could not decide beyond the symbolic budget ("
LATE_EXACT_THEN = ", so the exact method ran after all, beyond the budget"
LATE_MODULAR_MARK = "; the exact method, run after all beyond the budget: "


def expected_of(claim: Claim, method: str, verdict: str, n: int | None, r: int | None,
                variant: str | None) -> tuple[bool, bool]:
    """(whether the verdict is the one the catalog expects, whether the size is a documented erratum of the
    claim): the policy of :func:`_finish`, a function of the registered claim and the run (raises what the
    claim's fails_at raises)."""
    erratum = variant is None and bool(claim.erratum) and claim.expects_failure(n, r)
    if verdict == "undecided":
        return True, erratum
    if verdict in NEVER_EXPECTED:
        return False, erratum
    if method == "free":
        if verdict != "proved" or variant is not None:
            return verdict == "proved", erratum
        # a proof for every n, r contradicts a documented erratum at a size the claim is stated for
        return claim.expect != "fails" and not _erratum_at_a_stated_size(claim), erratum
    if erratum:                       # a documented erratum: expected to fail as printed, here
        return verdict == "fails", erratum
    return verdict in PASSING, erratum


#: what :func:`_finish` records of a run whose claim's erratum sizes (fails_at) raised: an error, not expected, no erratum
FAILS_AT_BROKE = {"verdict": "error", "expected": False, "erratum": "", "place": "", "slips": []}


def declared_fields(claim: Claim, method: str, verdict: str, n: int | None, r: int | None,
                    variant: str | None, policy: Callable | None = None) -> dict[str, Any]:
    """The fields of a record that the registered claim's declaration decides from the run's method, size,
    variant and verdict, as :func:`_finish` writes them: ``expected``, ``erratum`` (the claim's text where the
    size is a documented erratum) and ``place`` (where its misprint sits); where the claim's erratum sizes
    raise, :data:`FAILS_AT_BROKE` (with the verdict ``error`` the run then records).  One function for
    ``stiefelsym check`` and ``stiefelsym report --results``: a record's flags are checked for every verdict,
    those of a run that depends on time (inconclusive, error) included.  ``policy``: :func:`expected_of` unless
    given (the command line's runner's)."""
    try:
        expected, erratum = (policy or expected_of)(claim, method, verdict, n, r, variant)
    except Exception:   # noqa: BLE001 - the claim's own fails_at broke: what the run records then
        return dict(FAILS_AT_BROKE)
    return _flags(claim, expected, erratum)


def _flags(claim: Claim, expected: bool, erratum: bool) -> dict[str, Any]:
    """A record's flags from the policy's answer: whether expected, and at a documented erratum its text and the
    place of its misprint."""
    return {"expected": expected, "erratum": claim.erratum if erratum else "",
            "place": claim.place if erratum else "", "slips": list(claim.slips) if erratum else []}


def _erratum_at_a_stated_size(claim: Claim) -> bool:
    """Whether the claim documents an erratum at one of the sizes it is stated for (its planned sizes)."""
    return bool(claim.erratum) and any(claim.expects_failure(z.n, z.r) for z in claim.sizes)


def _finish(res: Result, claim: Claim, variant: str | None, hard: str | None = None) -> Result:
    """The verdict policy: which verdicts the catalog expects.

    ``undecided`` (the method does not apply here) is expected of every method;
    ``inconclusive`` (could not be decided numerically, or a budget was hit) and
    ``error`` never are; ``fails`` only where a documented erratum says so."""
    res.variant = variant
    if res.verdict == "inconclusive" and res.message.startswith("not applicable"):
        res.verdict = "undecided"     # the method has nothing to say here, e.g. float on a pure rank claim
    try:
        res.expected, erratum = expected_of(claim, res.method, res.verdict, res.n, res.r, variant)
    except (KeyboardInterrupt, Terminated):
        raise
    except BaseException as exc:  # noqa: BLE001 - the claim's own fails_at broke
        from stiefelsym.methods.fixed_size import _describe
        res.verdict = "error"
        res.message = f"the claim's erratum sizes (fails_at) could not be evaluated: {_describe(exc)}"
        res.expected, erratum = False, False
    flags = _flags(claim, res.expected, erratum)
    res.expected, res.erratum, res.place = flags["expected"], flags["erratum"], flags["place"]
    res.slips = flags["slips"]
    res.rerun = rerun_command(res, hard)
    return res


# --------------------------------------------------------------------------- the plan, in workers

def _execute(claims: list[Claim], seed: int, hard: str | None, timeout: float, in_worker: bool,
             task: Task, free: list | None = None, share: bool = False) -> Result:
    """Run one task (in a worker, unless fork is not available): the raw result.  ``free``: the dimension-free
    results of the task's claim and function that other workers kept (:func:`stiefelsym.methods.specialise.adopt`),
    taken as this worker's own; ``share``: the result says which this worker kept and has not handed over
    (:data:`FREE_KEPT`), for the other workers."""
    ci, n, r, method, k = task
    c = claims[ci]
    func = c.corrections[k].func if k >= 0 else None
    if k >= 0:
        c = c.corrected(k)
    size = None if n is None else Size(n, r)
    if free is not None:
        from stiefelsym.methods.specialise import adopt
        adopt(c, func, free)
    res = _guarded(c, size, method, seed, func, hard, in_worker=in_worker, timeout=timeout)
    if share:
        from stiefelsym.methods.specialise import take_kept
        setattr(res, FREE_KEPT, take_kept(c, func))
    if func is not None:
        # what a correction changes, read here, where its graph was traced for the run (and in parallel):
        # the parent reads it itself for a record computed at another size or not computed at all
        res.change = graph_change(claims[ci], func, size)
        res._change_at = (n, r)     # type: ignore[attr-defined]  (not a field: never in a record)
    return res


#: the attribute (not a field: never in a record) by which a worker's result carries the dimension-free results of
#: its claim the worker kept (its record with no size, the proofs of the attempts of its runs at a size) to the
#: parent, which hands them to the other workers with the claim's runs at a size: each dimension-free attempt of
#: auto and exact is then made once per run, not once per worker (the records are the same: the attempt is the
#: same computation)
FREE_KEPT = "_free_kept"


def _settle(outcome: Outcome, task: Task, claims: list[Claim], seed: int, hard: str | None) -> Result:
    """The finished result of a task, from what the pool reported (in the parent)."""
    ci, n, r, method, k = task
    c = claims[ci]
    size = None if n is None else Size(n, r)
    variant = c.corrections[k].description if k >= 0 else None
    res = outcome.value if outcome.kind == "ok" else None
    if res is not None and not (isinstance(res, Result) and res.verdict in VERDICTS
                                and res.claim == c.id and (res.n, res.r) == (n, r)):
        res = _error(c, size, method, seed, "the run did not return a result record for this claim and size")
    if res is None:
        res = _blank(c, size, method, seed)
        res.verdict = "inconclusive" if outcome.kind == "timeout" else "error"
        res.message = outcome.message
        res.seconds = outcome.seconds
    if k >= 0 and getattr(res, "_change_at", None) != (n, r):
        res.change = graph_change(c, c.corrections[k].func, size)
    return _finish(res, c, variant, hard)


#: a plan of at least this many runs imports sympy's matrices in the parent before forking, for the exact
#: runs that need them (ranks, symbolic rows); a shorter one leaves the import (0.4 s) to the run that needs
#: it, so a run of one claim at a few sizes whose exact proof needs no sympy starts 0.4 s sooner
PRELOAD_SYMPY_TASKS = 16


def _preload(tasks: list[Task], long_run: bool | None = None) -> None:
    """Import, before forking, what the workers will need (so a fresh worker starts ready); ``long_run``
    (default: a plan of :data:`PRELOAD_SYMPY_TASKS` runs or more) imports sympy's matrices too."""
    if any(t[1] is None for t in tasks):
        import sympy  # noqa: F401  (the LaTeX of symbolic coefficients in every derivation)
        from stiefelsym import free  # noqa: F401
        from stiefelsym.methods import dimension_free as free_method  # noqa: F401
    if long_run is None:
        long_run = len(tasks) >= PRELOAD_SYMPY_TASKS
    if long_run and any(t[3] in ("auto", "exact") for t in tasks):
        import sympy.polys.matrices  # noqa: F401


def verify(claims: list[Claim], *, sizes: list[Size] | None = None, methods: Iterable[str] = ("auto",),
           seed: int = 0, on_result: Callable[[Result], None] | None = None,
           on_plan: Callable[[int], None] | None = None, hard: str | None = None,
           timeout: float = DEFAULT_TIMEOUT, memory: float | None = DEFAULT_MEMORY_GIB, jobs: int = 1,
           strict_sizes: bool = False, fork: bool | None = None) -> list[Result]:
    """Run the plan, in order, in ``jobs`` worker processes; ``timeout`` seconds and ``memory``
    GiB (None: no limit) per run.

    Then, for every (claim, method) whose printed statement fails at some size, each
    registered correction is run at every planned size of that claim for that method:
    a correction is verified only where it holds everywhere.  ``on_result`` sees the
    results in that order (the plan first, then the corrections)."""
    if jobs < 1:
        raise ValueError("--jobs must be at least 1")
    methods = checked_options(seed, timeout, memory, hard, methods)
    claims = list(claims)
    runs = plan(claims, sizes, methods, strict=strict_sizes)
    if on_plan is not None:
        on_plan(len(runs))
    index = {id(c): i for i, c in enumerate(claims)}
    tasks: list[Task] = [(index[id(c)], None if s is None else s.n, None if s is None else s.r, m, -1)
                         for c, s, m in runs]
    memory_bytes = None if memory is None else int(memory * GIB)
    results: list[Result] = []

    # the dimension-free results the workers kept, by (claim, correction), each as its worker handed it over
    # (:data:`FREE_KEPT`): handed to every other worker with its next run at a size of the claim that may make the
    # attempt (auto, exact), so that no worker makes it again
    free_kept: dict[tuple[int, int], list[tuple]] = {}
    given: set[tuple[int, int, int, int]] = set()   # (worker, claim, correction, entry): that worker has it

    def execute(job: tuple[Task, list | None]) -> Result:
        return _execute(claims, seed, hard, timeout, pool.forking, job[0], job[1], share=True)

    def prepare(task: Task, worker: int) -> tuple[Task, list | None]:
        ci, n, _, method, k = task
        if n is None or method not in ("auto", "exact"):
            return task, None
        entries = free_kept.get((ci, k), [])
        new = [j for j in range(len(entries)) if (worker, ci, k, j) not in given]
        given.update((worker, ci, k, j) for j in new)
        return task, [entries[j] for j in new] or None

    def ended(task: Task, outcome: Outcome, worker: int) -> None:
        if outcome.kind == "ok" and isinstance(outcome.value, Result):
            ci, k = task[0], task[4]
            entries = free_kept.setdefault((ci, k), [])
            for entry in outcome.value.__dict__.pop(FREE_KEPT, None) or ():
                given.add((worker, ci, k, len(entries)))    # its worker keeps it
                entries.append(entry)

    def deliver(res: Result) -> None:
        results.append(res)
        if on_result is not None:
            on_result(res)

    if not tasks:
        return results
    _preload(tasks)
    from stiefelsym.methods.fixed_size import _describe
    with WorkerPool(execute, workers=min(jobs, len(tasks)), timeout=timeout, memory=memory_bytes,
                    describe=_describe, fork=fork) as pool:
        # a worker keeps to one claim's runs while there are others for the other workers: what it computed of the
        # claim (its graphs, its dimension-free proof) serves the claim's other runs (the records are the same)
        run_with_corrections(lambda tasks: pool.run(tasks, affinity=_claim_of, prepare=prepare, on_outcome=ended),
                             tasks, claims, seed, hard, deliver,
                             streams=True)
    return results


def _claim_of(task: Task) -> int:
    """The claim a task runs (the pool's affinity: a worker takes the runs of the claim it ran last first)."""
    return task[0]


def checked_options(seed: int, timeout: float, memory: float | None, hard: str | None,
                    methods: Iterable[str]) -> list[str]:
    """The checks every way of running a plan makes of its options; the methods to run (a hard
    case has nothing to say to the dimension-free method and refuses the symbolic one)."""
    if seed < 0:
        raise ValueError("the seed must be a non-negative integer")
    for name, x in (("timeout", timeout), ("memory", memory)):
        if x is not None and amount_problem(name, x):
            raise ValueError(amount_problem(name, x))
    methods = list(methods)
    if hard is not None:
        hard_case(hard)
        methods = [m for m in methods if m != "free"]
        if "exact" in methods:
            raise ValueError("hard cases are sampled points: use --method rational, modular or float")
    return methods


def run_with_corrections(run: Callable[[list[Task]], Iterable[tuple[int, Outcome]]], tasks: list[Task],
                         claims: list[Claim], seed: int, hard: str | None,
                         deliver: Callable[[Result], None], streams: bool = False) -> None:
    """Run the plan with ``run`` (local workers or a cluster: it yields (task index, outcome)),
    then every registered correction of each (claim, method) that failed somewhere, at every
    planned size of that claim and method, and of each claim the dimension-free method did not
    prove as printed (a correction proved for all n, r)."""
    failed: dict[tuple[int, str], None] = {}
    corrections: list[Task] = []
    copies: dict[int, int] = {}
    for i, outcome in _run_shared(run, tasks, claims, streams, copies):
        res = _settle(outcome, tasks[i], claims, seed, hard)
        _mark_copy(res, tasks, copies.get(i))
        deliver(res)
        ci, n, _, m, _ = tasks[i]
        if res.verdict == "fails" and n is not None and claims[ci].corrections:
            failed.setdefault((ci, m))
        if n is None and res.verdict != "proved":
            corrections += [(ci, None, None, m, k) for k in range(len(claims[ci].corrections))]
    for ci, m in failed:
        planned = [(t[1], t[2]) for t in tasks if t[0] == ci and t[3] == m and t[1] is not None]
        for k in range(len(claims[ci].corrections)):
            corrections += [(ci, n, r, m, k) for n, r in planned]
    if corrections:
        copies = {}
        for i, outcome in _run_shared(run, corrections, claims, streams, copies):
            res = _settle(outcome, corrections[i], claims, seed, hard)
            _mark_copy(res, corrections, copies.get(i))
            deliver(res)


def _mark_copy(res: Result, tasks: list[Task], source: int | None) -> None:
    """Mark ``res`` as the copy of the record of ``tasks[source]`` (:data:`COPY_OF`), when it is one."""
    if source is not None:
        setattr(res, COPY_OF, (tasks[source][1], tasks[source][2]))


def _run_shared(run: Callable[[list[Task]], Iterable[tuple[int, Outcome]]], tasks: list[Task],
                claims: list[Claim], streams: bool = False,
                copies: dict[int, int] | None = None) -> Iterable[tuple[int, Outcome]]:
    """(task index, outcome) for every task, in order, with the tasks of a graph that involves no dimension r
    run once per n (:func:`shared_size`): the run at (n, r0) is every run at (n, r), its record copied to
    each r (tasks and outcomes stay one per (claim, size, method, variant), so every budget, record and
    report is as before).  ``copies`` (filled as the outcomes come): task index -> the index of the task whose
    outcome this one's is a copy of (the task at the size the run was made at, else the first of them).

    ``streams`` (``run`` draws its tasks from an iterator as its workers come free: the local pool): the
    runs to make are handed over as they are found, so that looking at the claims' graphs (which traces
    them, here) is done while the workers compute instead of before they start."""
    units: list[Task] = []
    unit_of: list[int] = []
    where: dict[Task, int] = {}

    def found() -> Iterator[Task]:
        for t in tasks:
            ci, n, r, m, k = t
            key = t
            # only the reviewed catalog's claims are traced here, in the parent, to plan: claim code of
            # anyone else runs in budgeted workers only (a claim that hangs or sleeps while traced)
            if n is not None and claims[ci].reviewed:
                c = claims[ci]
                shared = shared_size(c.corrected(k) if k >= 0 else c, Size(n, r),
                                     c.corrections[k].func if k >= 0 else None, screen=True)
                if shared is not None:
                    key = (ci, n, shared.r, m, k)
            j = where.get(key)
            if j is None:
                j = where[key] = len(units)
                units.append(key)
                unit_of.append(j)
                yield key
            else:
                unit_of.append(j)

    if streams:
        outcomes = run(found())     # type: ignore[arg-type]  (the local pool takes an iterator)
    else:
        for _ in found():
            pass
        if len(units) == len(tasks):
            yield from run(tasks)
            return
        outcomes = run(units)
    done: dict[int, Outcome] = {}
    position = {t: k for k, t in enumerate(tasks)} if copies is not None else {}
    first: dict[int, int] = {}      # unit -> the task whose record the others copy: the one at the size it ran at
    i = 0

    def ready() -> Iterator[tuple[int, Outcome]]:
        # unit_of is known up to the last task looked at: a later task follows once it is (when the runs
        # are over every task has been looked at, and its unit is done)
        nonlocal i
        while i < len(unit_of) and unit_of[i] in done:
            got = done[unit_of[i]]
            r = tasks[i][2]
            if got.kind == "ok" and isinstance(got.value, Result) and r is not None and got.value.r != r:
                got = Outcome(got.kind, at_size(got.value, r), got.message, got.seconds)
            if copies is not None:
                k = first.setdefault(unit_of[i], position.get(units[unit_of[i]], i))
                if k != i:
                    copies[i] = k
            yield i, got
            i += 1

    for j, outcome in outcomes:
        done[j] = outcome
        yield from ready()
    yield from ready()


def rerun_command(result: Result, hard: str | None = None) -> str:
    parts = ["stiefelsym", "verify", result.claim]
    if result.n is not None:
        parts += ["--size", f"{result.n},{result.r}"]
    parts += ["--method", result.method]
    if result.seed is not None:
        parts += ["--seed", str(result.seed)]
    if hard is None:
        text = next((h for h in result.reductions if h.startswith("hard case: ")), None)
        if text is not None:
            from stiefelsym.methods.hard import HARD_CASES
            hard = next((k for k, v in HARD_CASES.items() if v.description in text), None)
    if hard:
        parts += ["--hard", hard]
    return _command_line(tuple(parts))


@functools.lru_cache(maxsize=4096)
def _command_line(parts: tuple[str, ...]) -> str:
    """The words quoted for a shell and joined (a function of the words)."""
    return " ".join(shlex.quote(p) for p in parts)

