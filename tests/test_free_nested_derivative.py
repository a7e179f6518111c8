"""Derivatives along flows nested in derivatives under the dimension-free method.

The free scene differentiates a function by dual numbers over the free algebra, and they do not nest: a tangent
scene's primitives are the letters X, P moved once, so a derivative taken inside a function whose derivative is
taken mixed the two levels (``TypeError: cannot add a r×r and a n×r polynomial``) or refused a flow of the outer
level.  The graph now writes a nested derivative as nodes over the enclosing function's scene and differentiates
them along the outer flow (:func:`stiefelsym.ir.derivative._nested`, on a scene that says
``NESTED_DERIVATIVES``: the free scene); what it cannot write so is refused with its reason.  Claims ending in
-true are true, those ending in -false false; the fixed-size methods keep the scene's own dual numbers."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
REVIEW = ROOT / "tests" / "adversary" / "s75" / "review" / "free_nested_d.py"
OWN = ROOT / "tests" / "claims_free_nested.py"


def _verdicts(claims: Path, method: str, *extra: str) -> dict[str, dict]:
    """{claim id: its record} of one `stiefelsym verify` run of a claims file (JSON, no report)."""
    run = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(claims), "--method", method,
                          *extra, "--jobs", "1", "--format", "json", "--no-report"],
                         cwd=ROOT, capture_output=True, text=True, timeout=600)
    recs = json.loads(run.stdout)["results"]
    assert recs, run.stdout[-2000:] + run.stderr[-2000:]
    return {r["claim"]: r for r in recs}


@pytest.fixture(scope="module")
def free():
    return {**_verdicts(REVIEW, "free"), **_verdicts(OWN, "free")}


@pytest.fixture(scope="module")
def exact():
    return {**_verdicts(REVIEW, "exact", "--size", "3,2"), **_verdicts(OWN, "exact", "--size", "3,2")}


def test_the_true_claims_are_proved_for_every_n_r(free):
    true = {cid: r for cid, r in free.items() if cid.endswith("-true")}
    assert len(true) == 19
    assert {cid: r["verdict"] for cid, r in true.items()} == {cid: "proved" for cid in true}, \
        {cid: r["message"] for cid, r in true.items() if r["verdict"] != "proved"}


def test_the_false_claims_are_never_proved(free):
    false = {cid: r for cid, r in free.items() if cid.endswith("-false")}
    assert len(false) == 18
    for cid, r in false.items():
        assert r["verdict"] not in ("proved", "checked", "numeric"), (cid, r["verdict"])
        # decided as far as the free method decides: a nonzero normal form, or a refusal with its reason (never
        # an operation of the free algebra raising)
        assert "TypeError" not in r["message"], (cid, r["message"])
    # the review's false claims and the own ones the graph writes as nodes: a residual with a nonzero normal form
    for cid in ("s75-nd-xtx-false", "s75-nd-matrix-false", "s75-nd-p-direction-false", "fnd-third-false",
                "fnd-moving-flow-false", "fnd-captured-outer-false", "fnd-product-false", "fnd-bracket-false"):
        assert free[cid]["verdict"] == "undecided" and "nonzero normal form" in free[cid]["message"], free[cid]


def test_the_fixed_size_verdicts_are_the_scenes_own(exact):
    for cid, r in exact.items():
        want = "proved" if cid.endswith("-true") else "fails"
        assert r["verdict"] == want, (cid, r["verdict"], r["message"])


def test_only_a_scene_that_says_so_gets_the_nested_derivatives_as_nodes():
    """The fixed-size scenes keep the nested derivative a call node (their dual numbers nest); the free scene's
    graph has no derivative left, and its tangent steps are the claim's own."""
    import importlib.util

    from stiefelsym.free.scene import FreeScene
    from stiefelsym.ir import derivative as deriv
    from stiefelsym.ir.derivative import POINT_FLOWS, coverage, derivatives, scene_flows
    from stiefelsym.ir.graph import Named
    from stiefelsym.methods.fixed_size import _claim_graph
    from stiefelsym.scene import REALIZATIONS

    spec = importlib.util.spec_from_file_location("claims_free_nested_review", REVIEW)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    cons = REALIZATIONS["standard"]
    g = _claim_graph(mod.nd_quartic_true, None, None, (cons.name, cons.build))
    flows = scene_flows(FreeScene(lazy=True))
    assert deriv.NESTED_DERIVATIVES in flows and deriv.NESTED_DERIVATIVES not in POINT_FLOWS
    assert [why for _, why in coverage(g, "d", flows)] == [None, None]
    out = derivatives(g, flows)
    assert not any(op == "call" and a[1] == "d" for op, a in zip(out.ops, out.args))
    steps = [a for op, a in zip(out.ops, out.args) if op == "prim" and type(a[0]) is Named
             and a[0].qualname == deriv.TANGENT]
    assert steps and all(out.ops[a[1].i] == "scene" and out.args[a[1].i] == (0,) for a in steps)
    fixed = coverage(g, "d", POINT_FLOWS)
    assert len(fixed) == 2 and all(why is not None for _, why in fixed)


def test_the_free_tangent_scene_refuses_a_derivative_inside_it():
    """What the graph leaves to the scene (a derivative inside a function its dual numbers differentiate) is
    refused with its reason, not computed at the wrong level."""
    from stiefelsym.free.algebra import NeedsCoordinates
    from stiefelsym.free.scene import FreeScene

    s = FreeScene(lazy=True)
    V = s.fresh("n", "r")
    with pytest.raises(NeedsCoordinates, match="nested in a derivative"):
        s.d(lambda t: t.d(lambda u: u.tr(u.X.T @ u.X), {"X": V}), {"X": V})
