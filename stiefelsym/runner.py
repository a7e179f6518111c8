"""Plans and runs verifications: claims x sizes x methods -> Result records."""
from __future__ import annotations

import shlex
from typing import Callable, Iterable

from .claims import Claim, Registry, Size
from .hard import hard_case
from .methods import BUDGET, METHOD_RUNNERS, BudgetError, check_budget, expected_verdict  # noqa: F401 (BudgetError is part of the runner API)
from .results import Result
from .scene import SizeError

METHODS = ("auto", "exact", "rational", "modular", "float", "free")


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


def plan(claims: list[Claim], sizes: list[Size] | None, methods: Iterable[str]) -> list[tuple[Claim, Size | None, str]]:
    """Every (claim, size, method) to run; size None is a dimension-free run."""
    methods = list(methods)
    for m in methods:
        if m not in METHODS:
            raise ValueError(f"unknown method {m!r} (one of {', '.join(METHODS)})")
    if sizes is not None:
        for s in sizes:
            for m in methods:
                if m != "free":
                    check_budget(m, s.n, s.r)
        if not any(_sizes_for(c, sizes) for c in claims) and any(m != "free" for m in methods):
            wanted = ", ".join(f"({s.n},{s.r})" for s in sizes)
            raise SizeError(f"no selected claim is stated for size {wanted}")
    runs: list[tuple[Claim, Size | None, str]] = []
    for c in claims:
        for m in methods:
            if m == "free" or (m == "auto" and sizes is None):
                runs.append((c, None, "free"))
            if m == "free" or (m == "float" and c.kind == "dim"):
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


def run_one(claim: Claim, size: Size | None, method: str, seed: int, func: Callable | None = None,
            variant: str | None = None, hard: str | None = None) -> Result:
    """One result for one (claim, size, method); ``hard`` names a hard numerical case."""
    options = {"hard": hard_case(hard)} if hard else None
    try:
        res = _dispatch(claim, size, method, seed, func, options)
    except KeyboardInterrupt:
        raise
    except Exception as exc:   # a bug in the claim (or the engine): an "error" verdict, never a traceback
        from .isolate import ChildError
        from .methods import _base_result, _describe
        res = _base_result(claim, size.n if size else None, size.r if size else None,
                           "free" if size is None else method, seed)
        res.verdict = "error"
        res.message = str(exc) if isinstance(exc, ChildError) else _describe(exc)
    return _finish(res, claim, variant)


def _dispatch(claim: Claim, size: Size | None, method: str, seed: int, func: Callable | None,
              options: dict | None) -> Result:
    if method == "free" or size is None:
        from .free_method import run_free
        res = run_free(claim, func)
    elif method == "auto":
        res = _run_auto(claim, size, seed, func) if not options else \
            METHOD_RUNNERS["rational"](claim, size.n, size.r, seed, func, options)
    else:
        if options and method == "exact":
            raise ValueError("hard cases are sampled points: use --method rational, modular or float")
        res = METHOD_RUNNERS[method](claim, size.n, size.r, seed, func, options)
    return res


def _finish(res: Result, claim: Claim, variant: str | None) -> Result:
    res.variant = variant
    if res.method == "free":
        res.expected = res.verdict in ("proved", "undecided")
    elif res.verdict == "inconclusive" and res.message.startswith("not applicable"):
        res.expected = True
    else:
        res.expected = expected_verdict(claim, res.verdict, variant, res.n, res.r)
    if variant is None and claim.erratum and claim.expects_failure(res.n, res.r):
        res.erratum = claim.erratum
    res.rerun = rerun_command(res)
    return res


def _run_auto(claim: Claim, size: Size, seed: int, func: Callable | None) -> Result:
    if size.n <= min(claim.exact_max_n, BUDGET["exact"]):
        res = METHOD_RUNNERS["exact"](claim, size.n, size.r, seed, func)
        if res.verdict != "inconclusive":
            return res
        reason = res.message
        spent = res.seconds
    else:
        reason, spent = f"n = {size.n} is above this claim's symbolic budget (n <= {claim.exact_max_n})", 0.0
    res = METHOD_RUNNERS["modular"](claim, size.n, size.r, seed, func)
    res.message = "; ".join(m for m in (f"exact: {reason}" if reason else "", res.message) if m)
    res.seconds += spent
    return res


def verify(claims: list[Claim], *, sizes: list[Size] | None = None, methods: Iterable[str] = ("auto",),
           seed: int = 0, on_result: Callable[[Result], None] | None = None,
           on_plan: Callable[[int], None] | None = None, hard: str | None = None) -> list[Result]:
    """Run the plan; claims that fail as printed are followed by their registered corrections."""
    if seed < 0:
        raise ValueError("the seed must be a non-negative integer")
    if hard is not None:
        hard_case(hard)
        methods = [m for m in methods if m != "free"]
        if "exact" in methods:
            raise ValueError("hard cases are sampled points: use --method rational, modular or float")
    runs = plan(claims, sizes, methods)
    if on_plan is not None:
        on_plan(len(runs))
    results: list[Result] = []
    for c, s, m in runs:
        res = run_one(c, s, m, seed, hard=hard)
        results.append(res)
        if on_result is not None:
            on_result(res)
        if res.verdict == "fails" and res.variant is None and c.corrections and s is not None:
            for corr in c.corrections:
                fix = run_one(c, s, m, seed, corr.func, corr.description, hard=hard)
                results.append(fix)
                if on_result is not None:
                    on_result(fix)
    return results


def rerun_command(result: Result) -> str:
    parts = ["stiefelsym", "verify", result.claim]
    if result.n is not None:
        parts += ["--size", f"{result.n},{result.r}"]
    parts += ["--method", result.method]
    if result.seed is not None:
        parts += ["--seed", str(result.seed)]
    hard = next((h for h in result.reductions if h.startswith("hard case: ")), None)
    if hard is not None:
        from .hard import HARD_CASES
        name = next((k for k, v in HARD_CASES.items() if v.description in hard), None)
        if name:
            parts += ["--hard", name]
    return " ".join(shlex.quote(p) for p in parts)
