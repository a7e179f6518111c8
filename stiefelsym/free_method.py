"""The dimension-free method: rewriting modulo the constraints (all n, r at once)."""
from __future__ import annotations

import time
from typing import Callable

from .claims import Claim
from .results import Result


def run_free(claim: Claim, func: Callable | None = None) -> Result:
    t0 = time.perf_counter()
    res = Result(claim=claim.id, paper=list(claim.paper), section=claim.section, kind=claim.kind,
                 title=claim.title, statement=claim.statement, n=None, r=None, method="free",
                 verdict="undecided", expected=True, seconds=0.0, seed=None)
    res.message = "the dimension-free backend is not available yet"
    res.seconds = time.perf_counter() - t0
    return res
