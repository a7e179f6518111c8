"""The trade-off table of the flows report: error within a wall-time budget and the time to reach a target."""
from __future__ import annotations

import math

import pytest

from stiefelsym.reports import flows_report as fr


def run(method, seconds, H, lax=float("nan"), constraint=1e-15, step=None, tol=None, flow="f"):
    return {"flow": flow, "flow_name": "neumann", "n": 4, "r": 2, "T": 50.0, "method": method, "tol": tol, "step": step,
            "seconds": seconds, "hamiltonian_error": H, "lax_error": lax, "constraint_error": constraint}


def test_time_to_a_target_is_interpolated_log_log_between_the_settings_around_it():
    rows = [run("rattle", 0.01, 1e-4, step=0.1), run("rattle", 0.1, 1e-6, step=0.01), run("rattle", 1.0, 1e-8, step=0.001)]
    assert fr._time_to(rows, 1e-6) == pytest.approx(0.1)
    assert fr._time_to(rows, 1e-7) == pytest.approx(math.sqrt(0.1 * 1.0))
    assert fr._time_to(rows, 1e-9) is None
    assert fr._time_to(rows, 1e-3) == pytest.approx(0.01)       # the cheapest setting already reaches it


def test_the_lax_drift_counts_when_it_is_larger_than_the_energy_error():
    rows = [run("rk4", 0.05, 1e-9, lax=1e-5, step=0.1), run("rk4", 0.5, 1e-12, lax=1e-9, step=0.01)]
    t = fr._tradeoffs(rows)[0]
    assert t["within_0.1s"]["setting"] == "h = 0.1"
    assert t["within_1s"]["setting"] == "h = 0.01" and t["best"]["error"] == pytest.approx(1e-9)
    assert t["seconds_to_1e-08"] is not None and 0.05 < t["seconds_to_1e-08"] < 0.5


def test_a_budget_no_setting_meets_is_empty_and_failed_runs_are_counted():
    rows = [run("rattle4", 0.5, 1e-6, step=0.1), run("rattle4", float("nan"), float("nan"), step=0.2)]
    rows[1]["failed"] = "SHAKE did not converge"
    t = fr._tradeoffs(rows)[0]
    assert t["within_0.1s"] is None and t["within_1s"]["setting"] == "h = 0.1"
    assert t["failed"] == 1
    md = fr._tradeoff_section({"meta": {"numpy": "x", "machine": "y"}, "work_precision": rows})
    assert "| f (4,2, 50) | RATTLE4, Yoshida | – | h = 0.1 |" in md
