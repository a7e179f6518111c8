"""Amounts a user gives (seconds, GiB) and numbers a results file holds: nan and inf are bad input.

A review found `--timeout inf` and `--memory inf` (or nan) ending in a traceback (select() and int() of an infinite
number), `--timeout nan` switching the time limit off (nan passes every comparison of a range), and a results file
whose check records a negative degree rendered by `report`."""
from __future__ import annotations

import copy
import json

import pytest

from stiefelsym.results import record_problems


@pytest.mark.parametrize("option,value", [("--timeout", "inf"), ("--timeout", "nan"), ("--timeout", "1e300"),
                                          ("--memory", "inf"), ("--memory", "nan"), ("--budget", "nan"),
                                          ("--budget", "-inf")])
def test_an_amount_that_is_not_a_finite_positive_number_is_bad_input(run, option, value):
    out = run("verify", "neumann-lax", "--size", "3,2", "--method", "modular", option, value)
    assert out.exit_code == 2, out.output
    assert "Invalid value for" in out.output and option in out.output
    assert "Traceback" not in out.output


def test_the_library_refuses_them_too():
    from stiefelsym.run.runner import checked_options
    for timeout, memory in ((float("nan"), 1.0), (float("inf"), 1.0), (10.0, float("nan")), (10.0, float("inf"))):
        with pytest.raises(ValueError, match="(timeout|memory) must be a positive number"):
            checked_options(0, timeout, memory, None, ["modular"])
    assert checked_options(0, 10.0, None, None, ["modular"]) == ["modular"]


def _record():
    return {"claim": "neumann-lax", "n": 3, "r": 2, "method": "modular", "verdict": "checked", "seed": 0,
            "false_pass_bound": 1e-30,
            "checks": [{"name": "LA1", "status": "zero", "detail": "", "degree": 12}]}


def test_a_negative_degree_or_a_bound_above_one_is_a_malformed_record():
    assert record_problems(_record()) == []
    for edit in (lambda d: d["checks"][0].update(degree=-5), lambda d: d.update(false_pass_bound=2.0)):
        d = copy.deepcopy(_record())
        edit(d)
        assert record_problems(json.loads(json.dumps(d))), d


def test_the_versions_in_a_report_are_importlib_metadata_s():
    """The run's package versions are read off the dist-info folders' names (importlib.metadata's import alone
    was a tenth of a short run's start-up); they are the versions importlib.metadata gives."""
    import importlib.metadata
    from stiefelsym.cli import VERSIONED, _versions
    got = _versions()
    for dist in VERSIONED:
        try:
            want = importlib.metadata.version(dist)
        except importlib.metadata.PackageNotFoundError:
            continue
        assert got[dist] == want, dist


def test_a_combining_mark_after_any_letter_is_its_accent_in_latex():
    """𝒳̇ and Ż̄ (a dot, then a bar) in a claim's text were printed in the report as the mark's code, [U+0307] and
    [U+0304]; a mark after a script (²̄) still is, since an accent on a superscript is no LaTeX."""
    from stiefelsym.latex import tex_escape
    assert tex_escape("𝒳̇") == r"\ensuremath{\dot{\mathcal{X}}}"
    assert tex_escape("Ż̄") == r"\ensuremath{\bar{\dot{Z}}}"
    assert tex_escape("Q̇") == r"\ensuremath{\dot{Q}}"
    assert "[U+0304]" in tex_escape("a²̄")
