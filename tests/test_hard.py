"""The hard sizes of the speed report: n = 200 (r = 1, 2), r = n and r = n - 1.  A true claim never
gets `fails`, the corrupted big Lax equation never gets a pass (at a plain random point it is
refuted), and a size the cost model predicts beyond the run's budget is not run (`refused`, never a
wrong verdict)."""
from stiefelsym.analyses import speed as sp


def test_r_equals_n_and_n_minus_1(catalog):
    plan = (("r = n", None, ("neumann-lax", "corrupted-LA1"), ((4, 4),), ("float", "modular"), 60.0),
            ("r = n - 1", None, ("neumann-flow", "corrupted-LA1"), ((4, 3),), ("float",), 60.0),
            ("r = n + near-pole-1e-8", "near-pole-1e-8", ("neumann-lax", "corrupted-LA1"), ((3, 3),), ("float",),
             60.0))
    rows = sp.hard_sizes_table(plan, registry=catalog)
    assert len(rows) == 8
    assert not [r for r in rows if r["judgement"].startswith("WRONG")], rows
    for r in rows:
        if r["truth"] == "true":
            assert r["verdict"] in ("numeric", "checked", "undecided"), r
        else:
            assert r["verdict"] == "fails", r
    # a plain random point gives a real verdict; a hard point only "resolved there"
    assert {r["verdict"] for r in rows if r["truth"] == "true" and r["case"] == "r = n + near-pole-1e-8"} == {"undecided"}
    # the float rows of the true claims were checked against the exact values at the same point
    floats = [r for r in rows if r["method"] == "float" and r["truth"] == "true"]
    assert floats and all(r["bound"] is not None and r["actual_error"] <= r["bound"] for r in floats), floats


def test_n_200_float_is_a_real_verdict(catalog):
    plan = (("n = 200", None, ("neumann-flow",), ((200, 1),), ("float",), 60.0),
            ("n = 200", None, ("corrupted-LA1",), ((200, 1),), ("modular",), 60.0))
    rows = sp.hard_sizes_table(plan, registry=catalog)
    got = {r["claim"]: r for r in rows}
    assert got["neumann-flow"]["verdict"] == "numeric" and got["neumann-flow"]["precision"] == "float64"
    assert got["corrupted-LA1"]["verdict"] == "fails"


def test_a_size_beyond_the_budget_is_refused_not_judged(catalog):
    plan = (("r = n", None, ("neumann-lax",), ((40, 40),), ("exact",), 1.0),)
    rows = sp.hard_sizes_table(plan, registry=catalog)
    assert [r["verdict"] for r in rows] == ["refused"]
    assert rows[0]["judgement"] == "ok" and "predicts" in rows[0]["reason"]
    md = sp.hard_markdown([], rows)
    assert "Hard sizes" in md and "refused" in md and "0 runs, 0 wrong verdicts" in md


def test_judgement_of_the_hard_sizes():
    assert "WRONG" in sp._judge("true", "fails", None)
    assert "WRONG" in sp._judge("false", "numeric", None)
    assert "WRONG" in sp._judge("false", "checked", None)
    assert sp._judge("true", "inconclusive", None) == "ok"
