"""The budget options of a rerun command: the run again gets the time, cost and memory budgets the
first run had (the command line and the Python API add them alike)."""
from __future__ import annotations

import shlex
from typing import Any, Sequence

from stiefelsym.run.pool import DEFAULT_MEMORY_GIB, DEFAULT_TIMEOUT


def budget_options(timeout: float, budget: float | None, memory: float | None) -> list[str]:
    """The options a rerun command adds for budgets other than the command line's defaults (the run
    again gets the time, cost and memory budgets the first run had)."""
    from stiefelsym.methods.costmodel import DEFAULT_BUDGET
    out: list[str] = []
    if timeout != DEFAULT_TIMEOUT:
        out += ["--timeout", f"{timeout:g}"]
    if budget is not None and budget != DEFAULT_BUDGET:
        out += ["--budget", f"{budget:g}"]
    if memory is not None and memory != DEFAULT_MEMORY_GIB:
        out += ["--memory", f"{memory:g}"]
    return out


def with_budgets(result: Any, options: Sequence[str]) -> None:
    """Add the budget options (:func:`budget_options`) to the result's rerun command, once."""
    if options and result.rerun and options[0] not in result.rerun:
        result.rerun += " " + shlex.join(options)
