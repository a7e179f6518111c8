"""Fresh elements (s.fresh): generic elements numbered by the engine, new at every call, that no claim can name;
the test elements of brackets.poisson_checks and brackets.compatibility."""
from __future__ import annotations

import pytest

from stiefelsym import brackets as B
from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.ir import compile_claim
from stiefelsym.ir.mutants import graph_mutants
from stiefelsym.ir.notation import outputs, render
from stiefelsym.ir.replay import GraphClaim
from stiefelsym.ir.trace import TraceRefused, trace
from stiefelsym.run.runner import run_one
from stiefelsym.scene import REALIZATIONS

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)


def _graph(func):
    return compile_claim(func, None, None, CONS)


def _claim(func, cid="fresh-toy"):
    return Claim(id=cid, paper=("toy",), kind="pb", section="", func=func, sizes=admissible(n_max=3))


def two_fresh(s):
    x, y = s.fresh("n", "n"), s.fresh("n", "n")
    return {"x - y": x - y, "x - G": x - s.generic("G", "n", "n")}


def test_each_call_is_a_new_element_numbered_by_the_engine():
    g = _graph(two_fresh)
    calls = [a[2] for op, a in zip(g.ops, g.args) if op == "call" and a[1] == "fresh"]
    assert calls == [(1, "n", "n"), (2, "n", "n")]
    assert _graph(two_fresh).digest() == g.digest()          # the same numbers in every trace


def test_fresh_elements_are_neither_equal_nor_a_claims_generic_element():
    c = _claim(two_fresh)
    for method in ("rational", "modular", "float"):
        assert run_one(c, Size(3, 2), method, 0).verdict == "fails", method
    assert run_one(c, None, "free", 0).verdict != "proved"


def test_a_claim_cannot_give_the_number():
    def numbered(s):
        return {"x": s.fresh(1, "n", "n")}
    with pytest.raises((TraceRefused, TypeError)):
        _graph(numbered)


def test_replay_and_notation():
    g = _graph(two_fresh)
    again = trace(GraphClaim(g), None, None, CONS)
    assert again.digest() == g.digest()
    text = {name: render(g, v) for name, v in outputs(g)}
    assert text["x - y"] == "w̃₁ − w̃₂", text
    assert render(g, dict(outputs(g))["x - G"], tex=True) == r"\tilde w_{1} - G", text


def test_direct_calls_on_a_scene_draw_new_elements():
    import random

    from stiefelsym.backends.fields import ModularField
    from stiefelsym.scene import Scene
    s = Scene(3, 2, ModularField(), rng=random.Random("fresh"))
    x, y = s.fresh("n", "n"), s.fresh("n", "n")
    assert not s.field.is_zero((x - y)[0, 1])


def _tensor_at(point):
    def form(t, x, a, b):
        d = x - point(t)
        return t.tr(x.T @ (a @ b - b @ a)) + t.tr(d.T @ d) * t.tr(a.T @ b)
    return B.PoissonTensor(B.SO_N, form, 2, "LP + |x - x0|^2 <a, b>")


def test_poisson_checks_draw_fresh_elements_at_every_call():
    """Two calls draw ten elements; a tensor built on one the claim drew itself (negative control) fails."""
    def twice(s):
        out = B.poisson_checks(s, B.lie_poisson(B.SO_N), "one")
        out.update(B.poisson_checks(s, B.lie_poisson(B.SO_N), "two"))
        return out
    g = _graph(twice)
    assert sorted(a[2][0] for op, a in zip(g.ops, g.args) if op == "call" and a[1] == "fresh") == list(range(1, 11))
    ok = _claim(twice)
    for method in ("exact", "modular", "float"):
        assert run_one(ok, Size(3, 2), method, 0).verdict in ("proved", "checked", "numeric"), method
    assert run_one(ok, None, "free", 0).verdict == "proved"

    def own(s):
        w = B.SO_N.fresh(s)
        return B.poisson_checks(s, _tensor_at(lambda t: w))
    bad = _claim(own)
    for method in ("exact", "modular", "float"):
        assert run_one(bad, Size(3, 2), method, 0).verdict == "fails", method


def test_a_tensor_that_keeps_a_point_keeps_a_parameter():
    """The form is traced as a function of (x, a, b) at each evaluation: a point it keeps is a parameter of that
    function, which the graph cannot use elsewhere: the tracer refuses it (error, never a verdict)."""
    def keeper(s):
        seen = []

        def form(t, x, a, b):
            seen.append(x)
            d = x - seen[0]
            return t.tr(x.T @ (a @ b - b @ a)) + t.tr(d.T @ d) * t.tr(a.T @ b)
        return B.poisson_checks(s, B.PoissonTensor(B.SO_N, form, 2, "keeper"))
    c = _claim(keeper)
    for method in ("exact", "modular", "float"):
        assert run_one(c, Size(3, 2), method, 0).verdict == "error", method
    assert run_one(c, None, "free", 0).verdict not in ("proved", "checked", "numeric")


def test_a_parameter_kept_from_another_function_is_refused_when_traced():
    def kept(s):
        seen = []

        def spy(t, x, a, b):
            seen.append(x)
            return t.tr(x.T @ (a @ b - b @ a))
        B.poisson_checks(s, B.PoissonTensor(B.SO_N, spy, 1, "spy"))
        return {"kept": seen[-1] - s.generic("G", "n", "n")}
    with pytest.raises(TraceRefused, match="parameter used outside the function"):
        _graph(kept)


def test_graph_mutants_of_a_claim_with_fresh_elements():
    def pencil(s):
        out = B.poisson_checks(s, B.lambda2(), "Lambda2")
        out.update(B.compatibility(s, B.lambda1(), B.lambda2(), "pencil"))
        return out
    g = _graph(pencil)
    ms = list(graph_mutants(g, CONS))
    assert ms
    for m in ms[:20]:
        fresh = [a[2] for op, a in zip(m.graph.ops, m.graph.args) if op == "call" and a[1] == "fresh"]
        assert [f[0] for f in fresh] == list(range(1, len(fresh) + 1)), m
