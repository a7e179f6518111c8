"""The results file is json.dumps(payload, indent=1, default=str), byte for byte."""
from __future__ import annotations

import json
import math
from fractions import Fraction

from stiefelsym.results import SCHEMA_VERSION, CheckOutcome, Result, dump_results


def _result(**kw) -> Result:
    base = dict(claim="c", paper=["p"], section="9", kind="id", title="t — ü", statement=r"\lambda", n=3, r=2,
                method="modular", verdict="checked", expected=True, seconds=0.25, seed=0)
    base.update(kw)
    return Result(**base)


def test_dump_results_is_json_dumps_indented():
    results = [
        _result(),
        _result(n=None, r=None, method="free", verdict="proved", seconds=None, seed=None,
                checks=[CheckOutcome("x", "zero", "d\n\"q\"", 3), CheckOutcome("y", "rank")],
                witness={"point": {"a_1": "3", "k": [1, (2, 3), []]}, 7: {}, None: 1.5, True: -0.0,
                         "f": Fraction(1, 3), "inf": math.inf, "nan": math.nan, "e": 1e-300},
                certificate_data={"entries": [{"terms": [[1, "X"], [-2, "P"]]}], "about": {}},
                reductions=["équivariance", ""], derivation=["\\[x\\]"], change=[{"where": "", "old": ""}]),
    ]
    meta = {"seed": 0, "sizes": None, "versions": {"python": "3"}, "seconds": 1.5, "nested": [[], {}, [[1]]]}
    expected = json.dumps({"schema": SCHEMA_VERSION, "meta": meta, "results": [r.to_json() for r in results]},
                          indent=1, sort_keys=False, default=str) + "\n"
    assert dump_results(results, meta) == expected


def test_the_budgets_a_command_records_have_the_engines_defaults():
    """results.COMMAND_BUDGETS (which budgets a recorded command names, and which rerun commands must name) holds
    the defaults of the pool and the cost model: one table, read by the meta check and the rerun check alike."""
    from stiefelsym.methods.costmodel import DEFAULT_BUDGET
    from stiefelsym.results import COMMAND_BUDGETS
    from stiefelsym.run.pool import DEFAULT_MEMORY_GIB, DEFAULT_TIMEOUT
    assert {key: default for _, key, default in COMMAND_BUDGETS} == {
        "timeout": DEFAULT_TIMEOUT, "budget": DEFAULT_BUDGET, "memory_gib": DEFAULT_MEMORY_GIB}
