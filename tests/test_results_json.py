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


def test_a_records_place_of_a_misprint_is_a_string_and_optional(tmp_path):
    """A record carries the place of its erratum's misprint ("the proof of Theorem 7.1"); a record written before
    the field existed has none, and loads with an empty place."""
    from stiefelsym.results import load_results, record_problems
    r = Result(claim="c", paper=["NEUMANN2"], section="7", kind="dim", title="t", statement="", n=2, r=1,
               method="exact", verdict="fails", expected=True, seconds=0.1, seed=None, erratum="h is r x r.",
               place="the proof of Theorem 7.1")
    record = json.loads(dump_results([r], {}))["results"][0]
    assert record["place"] == "the proof of Theorem 7.1" and record_problems(record) == []
    assert any("place" in p for p in record_problems(dict(record, place=["the proof"])))
    old = {k: v for k, v in record.items() if k != "place"}
    path = tmp_path / "old.json"
    path.write_text(json.dumps({"schema": SCHEMA_VERSION, "meta": {}, "results": [old]}))
    assert load_results(path)[1][0].place == ""


def test_a_records_slips_are_strings_and_optional(tmp_path):
    """A record of an erratum carries the slips its text reports in passing; a record written before the field
    existed has none, and loads with none."""
    from stiefelsym.results import load_results, record_problems
    r = Result(claim="c", paper=["NEUMANN2"], section="7", kind="dim", title="t", statement="", n=2, r=1,
               method="exact", verdict="fails", expected=True, seconds=0.1, seed=None, erratum="h is r x r.",
               slips=["the subscript I_{r+1} for I_{l+1}"])
    record = json.loads(dump_results([r], {}))["results"][0]
    assert record["slips"] == ["the subscript I_{r+1} for I_{l+1}"] and record_problems(record) == []
    assert any("slips" in p for p in record_problems(dict(record, slips="the subscript")))
    old = {k: v for k, v in record.items() if k != "slips"}
    path = tmp_path / "old.json"
    path.write_text(json.dumps({"schema": SCHEMA_VERSION, "meta": {}, "results": [old]}))
    assert load_results(path)[1][0].slips == []
