"""Stop 94: the review's own trick on the exact method's chart skip (a graph that reads coordinates of ℝⁿ with
no reviewed reason of equivariance goes straight to the unconstrained or Cayley chart, without the equivariant
chart's evaluation first).  False statements that hold at the equivariant chart's reduced points X = (I; 0), beside
true twins, under every fixed-size method: no false one passes, no true one is refuted."""
from __future__ import annotations

from pathlib import Path

import pytest

import stiefelsym

FILE = str(Path(__file__).with_name("s94") / "own" / "chart_skip.py")
SIZES = [(3, 1), (4, 2), (3, 3)]
PASSING = {"proved", "checked", "numeric"}


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float", "ball"])
def test_a_statement_true_only_at_the_reduced_point_is_refuted_after_the_chart_skip(method):
    res = stiefelsym.verify(["s94-first-rows-unit", "s94-column-unit", "s94-last-row-zero", "s94-xtp-diag"],
                            files=FILE, sizes=SIZES, methods=[method], jobs=1)
    got = {(r.claim, r.n, r.r): r.verdict for r in res}
    for (cid, n, r), verdict in got.items():
        truth = cid in ("s94-column-unit", "s94-xtp-diag") or (cid == "s94-first-rows-unit" and r == n)
        if truth:
            assert verdict in PASSING, (cid, n, r, method, verdict)
        else:
            assert verdict == "fails", (cid, n, r, method, verdict)
    assert len(got) == 12
