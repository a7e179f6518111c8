"""The exact method's unconstrained chart: a graph that reads coordinates (the Cayley chart's domain) and holds
for independent generic X, P is proved there, a polynomial computation with no inverse of the chart; one that
needs the constraints, or divides by what vanishes on T*V, goes to the Cayley chart as before."""
from __future__ import annotations

from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.methods.fixed_size import UNCONSTRAINED_REDUCTION
from stiefelsym.run.runner import run_one

MARK = UNCONSTRAINED_REDUCTION[:40]


def _claim(func, cid="unconstrained-toy", expect="holds"):
    return Claim(id=cid, paper=("toy",), kind="id", section="", func=func, sizes=admissible(n_max=5), expect=expect)


def entry_identity(s):
    """True for every X, P: (XᵀP)₁₁ = Σ_i X_i1 P_i1, read entry by entry."""
    X, P = s.X, s.P
    acc = s.q(0)
    for i in range(s.n):
        acc = acc + X[i, 0] * P[i, 0]
    return {"(X^T P)_11 - sum": (X.T @ P)[0, 0] - acc}


def needs_the_constraint(s):
    """True on T*V only: (XᵀX)₁₁ = 1."""
    return {"(X^T X)_11 - 1": (s.X.T @ s.X)[0, 0] - s.q(1)}


def false_entry(s):
    return {"X_11 - P_11": s.X[0, 0] - s.P[0, 0]}


def zero_over_zero_on_tv(s):
    """Undefined on T*V: X₁₁·d/d with d = tr(XᵀX) − r, identically 0 on T*V (and 1 off it)."""
    d = s.tr(s.X.T @ s.X) - s.q(s.r)
    return {"X_11 d/d - X_11": s.X[0, 0] * d / d - s.X[0, 0]}


def zero_over_zero_on_a_component(s):
    """At r = n = 2, undefined on the component det X = 1 (d = det X − 1 vanishes there), 0 elsewhere."""
    X = s.X
    d = X[0, 0] * X[1, 1] - X[0, 1] * X[1, 0] - s.q(1)
    return {"X_11 d/d - X_11": X[0, 0] * d / d - X[0, 0]}


def test_an_identity_without_the_constraints_is_proved_on_the_unconstrained_chart():
    for size in (Size(3, 2), Size(4, 4)):
        r = run_one(_claim(entry_identity), size, "exact", 0)
        assert r.verdict == "proved", r.message
        assert any(x.startswith(MARK) for x in r.reductions), r.reductions


def test_an_identity_that_needs_the_constraints_goes_to_the_cayley_chart():
    r = run_one(_claim(needs_the_constraint), Size(3, 2), "exact", 0)
    assert r.verdict == "proved", r.message
    assert not any(x.startswith(MARK) for x in r.reductions), r.reductions


def test_a_false_identity_fails_with_a_witness():
    r = run_one(_claim(false_entry), Size(3, 2), "exact", 0)
    assert r.verdict == "fails" and r.witness


def test_a_division_by_what_vanishes_on_tv_is_never_proved():
    """0 off T*V, 0/0 on it: the unconstrained evaluation alone would say 0."""
    r = run_one(_claim(zero_over_zero_on_tv), Size(3, 2), "exact", 0)
    assert r.verdict != "proved", (r.verdict, r.reductions)
    assert not any(x.startswith(MARK) for x in r.reductions)


def test_a_division_by_what_vanishes_on_one_component_is_not_proved_on_the_unconstrained_chart():
    r = run_one(_claim(zero_over_zero_on_a_component), Size(2, 2), "exact", 0)
    assert not any(x.startswith(MARK) for x in r.reductions), (r.verdict, r.reductions)


def test_a_claim_said_not_to_vanish_is_not_decided_there():
    r = run_one(_claim(false_entry, expect="nonzero"), Size(3, 2), "exact", 0)
    assert r.verdict == "proved" and not any(x.startswith(MARK) for x in r.reductions)
    r = run_one(_claim(entry_identity, expect="nonzero"), Size(3, 2), "exact", 0)
    assert r.verdict == "fails"


def test_the_catalog_claims_of_the_chart():
    """2r-integrals-explicit and mum-geod hold without the constraints: proved there, at sizes the Cayley
    chart takes seconds (or is beyond its memory) for."""
    from stiefelsym.claims import load_catalog
    cat = {c.id: c for c in load_catalog()}
    for cid, size in (("2r-integrals-explicit", Size(4, 2)), ("mum-geod", Size(5, 1))):
        r = run_one(cat[cid], size, "exact", 0)
        assert r.verdict == "proved", (cid, r.message)
        assert any(x.startswith(MARK) or f": {MARK}" in x for x in r.reductions), (cid, r.reductions)


def test_a_graph_that_reads_coordinates_without_a_reason_skips_the_equivariant_chart(monkeypatch):
    """Its looks at coordinates are recorded before any evaluation and no reviewed reason can be relied on: the
    equivariant chart's values would be dropped, so it is not evaluated; the verdict and the record are the same."""
    import stiefelsym.methods.fixed_size as fs
    from stiefelsym.claims import load_catalog

    charts: list = []
    chart_checks = fs._chart_checks

    def recording(key, *args, **kw):
        charts.append(key[5])
        return chart_checks(key, *args, **kw)
    monkeypatch.setattr(fs, "_chart_checks", recording)
    toy = fs.run_exact(_claim(entry_identity), 3, 2, 0)
    assert toy.verdict == "proved" and any(d.startswith(MARK) for d in toy.reductions), toy.reductions
    tangency = fs.run_exact(load_catalog().get("tangency"), 4, 2, 0)
    assert tangency.verdict == "proved" and any(d.startswith(MARK) for d in tangency.reductions)
    assert "equivariant" not in charts and charts.count("unconstrained") == 2, charts
    # a graph that reads none goes to the equivariant chart as before
    charts.clear()
    assert fs.run_exact(_claim(lambda s: {"XtP": s.X.T @ s.P - s.X.T @ s.P}), 3, 2, 0).verdict == "proved"
    assert charts and charts[0] == "equivariant", charts
