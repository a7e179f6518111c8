"""Measuring the cost model: runs of each family's representative claim, for each method, at growing
n (the data :func:`stiefelsym.costmodel.build` fits).  It runs the methods, so it lives above them;
the model itself (:mod:`.costmodel`) only predicts."""
from __future__ import annotations

from typing import Any, Iterable, Sequence

from .costmodel import FAMILIES, METHODS, SMALL_R, BudgetError, _default_ns


def measure(methods: Iterable[str] = METHODS, families: dict[str, str] | None = None,
            n_values: dict[str, Sequence[int]] | None = None, per_run: float = 30.0,
            series_seconds: float = 20.0, seed: int = 0, on_point: Any = None,
            registry: Any = None, small_ns: dict[str, Sequence[int]] | None = None) -> list[dict[str, Any]]:
    """Time runs of each family's representative claim, for each method, at growing n.

    Each run executes in a budgeted worker (``runner.verify``); a series (r = ceil(n/2), and
    r = n with both components of O(n)) stops at the first run that is not decided in
    ``per_run`` seconds, or once it has spent ``series_seconds``.  Returns one record per run."""
    from .claims import Size, load_catalog
    from .runner import verify
    from .scene import SizeError
    from .runner import run_one
    families = families or FAMILIES
    small_ns = {} if small_ns is None else small_ns
    registry = registry or load_catalog()
    grid = n_values or {}
    out: list[dict[str, Any]] = []
    methods = list(methods)
    # warm up in this process: the workers are forked from it, so no run pays for first imports
    for cid in families.values():
        for method in methods:
            try:
                run_one(registry.get(cid), Size(2, 1), method, seed)
            except Exception:  # noqa: BLE001 - a warm-up only
                pass
    for fam, cid in families.items():
        claim = registry.get(cid)
        for method in methods:
            if method == "float" and claim.kind == "dim":
                continue
            spent = {"half": 0.0, "square": 0.0, "small": 0.0}
            # dimensions (exact ranks) grow like n^4 and more: no small-r series to n = 200
            stopped = {"half": False, "square": False, "small": method not in small_ns or claim.kind == "dim"}
            ns = sorted(set(grid.get(method, _default_ns(method))) | set(small_ns.get(method, [])))
            for n in ns:
                kinds = [("small", SMALL_R)] if n in small_ns.get(method, []) else []
                if n in grid.get(method, _default_ns(method)):
                    kinds = [("half", (n + 1) // 2), ("square", n)] + kinds
                for kind, r in kinds:
                    if stopped[kind] or (kind == "square" and r == (n + 1) // 2) or r > n:
                        continue
                    if kind == "small" and n < 2 * SMALL_R + 1:
                        continue
                    try:
                        results = verify([claim], sizes=[Size(n, r)], methods=(method,), seed=seed,
                                         timeout=per_run, jobs=1)
                    except (BudgetError, SizeError):
                        stopped[kind] = True
                        continue
                    res = next((x for x in results if x.variant is None), None)
                    if res is None:
                        continue
                    rec = {"family": fam, "claim": cid, "method": method, "n": n, "r": r,
                           "seconds": round(float(res.seconds), 6), "verdict": res.verdict}
                    if kind == "small":
                        rec["series"] = "small"
                    out.append(rec)
                    if on_point is not None:
                        on_point(rec)
                    spent[kind] += res.seconds
                    if res.verdict in ("inconclusive", "error") or spent[kind] > series_seconds:
                        stopped[kind] = True
                if all(stopped.values()):
                    break
    return out
