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


def _shared_pair() -> list[Result]:
    cert = {"format": "f", "entries": [{"terms": [[1, "X"]]}], "about": {"claim": "c", "digest": "d"}}
    return [_result(n=4, r=4, method="exact", verdict="proved", certificate_data=cert),
            _result(n=5, r=4, method="exact", verdict="proved", certificate_data=json.loads(json.dumps(cert))),
            _result(n=2, r=1, method="exact", verdict="proved", certificate_data={"format": "g", "about": {}})]


def test_a_certificate_several_records_carry_is_written_once_and_read_back_into_each(tmp_path):
    """A family's dimension-free proof specialised at several sizes is one certificate: the file holds it once,
    in its table "certificates" under the SHA-256 of its canonical JSON, the records refer to it, and loading
    puts it back in each record; a certificate of one record stays in its record."""
    from stiefelsym.results import certificate_key, load_results
    results = _shared_pair()
    text = dump_results(results, {})
    payload = json.loads(text)
    key = certificate_key(results[0].certificate_data)
    assert list(payload["certificates"]) == [key] and payload["certificates"][key] == results[0].certificate_data
    assert [r["certificate_data"] for r in payload["results"][:2]] == [{"shared": key}] * 2
    assert payload["results"][2]["certificate_data"] == {"format": "g", "about": {}}
    expected = json.dumps(dict(payload), indent=1, default=str) + "\n"
    assert text == expected   # still json.dumps's text, byte for byte
    path = tmp_path / "r.json"
    path.write_text(text)
    assert [r.to_json() for r in load_results(path)[1]] == [r.to_json() for r in results]
    assert "certificates" not in dump_results(results[1:], {})   # one carrier: nothing shared


def test_a_shared_certificate_that_is_not_the_one_its_key_names_is_refused(tmp_path, capsys):
    """Editing the shared certificate (or a reference to it) is caught on loading, by the check command and by
    the independent checker run on the file: the key is the digest of the certificate."""
    from stiefelsym.certificate_check import main as check_main
    from stiefelsym.results import load_results
    payload = json.loads(dump_results(_shared_pair(), {}))
    key = next(iter(payload["certificates"]))
    edited = json.loads(json.dumps(payload))
    edited["certificates"][key]["entries"] = []
    dangling = json.loads(json.dumps(payload))
    dangling["results"][0]["certificate_data"] = {"shared": "0" * 64}
    unused = json.loads(json.dumps(payload))
    unused["results"][0]["certificate_data"] = unused["results"][1]["certificate_data"] = None
    for name, bad, words in (("edited", edited, "not the one its key names"),
                             ("dangling", dangling, "does not hold"), ("unused", unused, "no result refers to")):
        path = tmp_path / f"{name}.json"
        path.write_text(json.dumps(bad))
        try:
            load_results(path)
        except ValueError as exc:
            assert words in str(exc)
        else:
            raise AssertionError(f"the {name} table was read")
        if name != "unused":
            assert check_main([str(path)]) == 1
            assert "REJECTED: it refers to a shared certificate" in capsys.readouterr().out


def test_the_checker_rejects_a_file_that_is_not_a_results_file(tmp_path, capsys):
    # the standalone checker says REJECTED (exit 1) for any shape of file, never a traceback
    from stiefelsym.certificate_check import main as check_main
    shapes = ['[1]', '{"certificates": [1], "results": []}', '{"results": 5}', '{"results": [3]}', 'not json',
              '{"results": [{"certificate_data": [1], "verdict": "proved"}]}',
              '{"results": [{"certificate_data": "text", "verdict": "proved"}]}',
              '{"results": [{"certificate_data": {"shared": 5}}]}']
    for i, text in enumerate(shapes):
        path = tmp_path / f"shape{i}.json"
        path.write_text(text)
        assert check_main([str(path)]) == 1, text
        assert "REJECTED" in capsys.readouterr().out, text
    assert check_main([str(tmp_path / "absent.json")]) == 1
    assert "not a readable JSON file" in capsys.readouterr().out
    deep = tmp_path / "deep.json"
    deep.write_text('{"results": ' + "[" * 100000 + "]" * 100000 + "}")
    assert check_main([str(deep)]) == 1 and "not a readable JSON file" in capsys.readouterr().out
    # a file with nothing to check says so (exit 0: nothing is rejected)
    for text in ("{}", '{"results": []}'):
        path = tmp_path / "empty.json"
        path.write_text(text)
        assert check_main([str(path)]) == 0 and "no certificate to check" in capsys.readouterr().out
