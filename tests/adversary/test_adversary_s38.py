"""Round 8 (tests/adversary/README.md, the "Round 8" table): the records shared across r (a graph that involves
no dimension r is run once per n), the component bits at r = n read through elementary() and det(), ranks whose
generic value differs between the components of O(n) x O(n), the reduced exact charts (the normal part
(I − XXᵀ)[0; Z2]) under ranks at every point and divisions, and residuals undefined at a stated size.  As before
every run is the CLI in a fresh process, and each test asserts the CORRECT outcome."""
import re

import pytest

from adversary_cli import HERE, PASSING, cli
from test_adversary_s33 import ALL_METHODS

#: "<claim> (n,r) <method>: <verdict>" or "<claim> all n, r free: <verdict>"
SIZED = re.compile(r"^(\S+) (?:\((\d+),(\d+)\)|all n, r) (\w+): (\w+)")


def run_sizes(claims_file, methods=ALL_METHODS, free=True, sizes=()):
    """{(claim, size, method): verdict} of one run of the fixed-size methods at every size the claims are
    stated for (or at ``sizes``), and of one run of free (size None).  auto names the method it chose."""
    args = ["verify", "--claims", str(HERE / claims_file), "--jobs", "1"]
    for size in sizes:
        args += ["--size", size]
    for m in methods:
        args += ["--method", m]
    runs = [cli(*args).stdout]
    if free:
        runs.append(cli("verify", "--claims", str(HERE / claims_file), "--method", "free", "--jobs", "1").stdout)
    got = {}
    for out in runs:
        for m in map(SIZED.match, out.splitlines()):
            if m:
                size = (int(m.group(2)), int(m.group(3))) if m.group(2) else None
                got.setdefault((m.group(1), size), set()).add((m.group(4), m.group(5)))
    return got


def verdicts(got, claim, size, free=False):
    """The verdicts of one claim at one size (free: its run for every n, r)."""
    return {v for m, v in got.get((claim, None if free else size), set())}


SHARED = "s38_shared_across_r.py"
N3 = [(3, 1), (3, 2), (3, 3)]


def test_a_graph_that_involves_no_r_is_shared_with_the_verdict_of_every_r():
    """A graph in A, λ and I_n alone is run once at (3, 1) and its record copied to (3, 2) and (3, 3) (the
    reduction is stated in the record); a claim with I_r (a leaf on ℝʳ) or a user scalar whose name is "r" is
    not shared by a mistake of the name: tr(I_r) = 1 passes at r = 1 only.  No hole: every verdict is the
    statement's at its own size, under every method."""
    got = run_sizes(SHARED)
    for size in N3:
        assert verdicts(got, "adv-s38-a-false", size) == {"fails"}, (size, got)
        assert verdicts(got, "adv-s38-a-cayley-hamilton", size) <= set(PASSING), (size, got)
        assert verdicts(got, "adv-s38-scalar-named-r", size) <= set(PASSING), (size, got)
        # an every-point rank that drops at λ = a_i: no method passes it; exact leaves it undecided (its rank
        # over the function field is the stated one and no constant maximal minor is nonzero, and a "fails"
        # needs a point where the rank drops), the sampled methods too
        rank = got[("adv-s38-resolvent-rank", size)]
        assert {v for _, v in rank} <= {"fails", "undecided"} and ("exact", "undecided") in rank, (size, rank)
        tr_ir = verdicts(got, "adv-s38-ir-named-r", size)
        assert tr_ir <= set(PASSING) if size == (3, 1) else tr_ir == {"fails"}, (size, tr_ir)
    assert verdicts(got, "adv-s38-a-false", None, free=True) == {"undecided"}
    assert verdicts(got, "adv-s38-ir-named-r", None, free=True) == {"undecided"}
    assert verdicts(got, "adv-s38-scalar-named-r", None, free=True) == {"proved"}


CHARTS = "s38_components_and_charts.py"
COMPONENT_FALSE = ("adv-s38-e2-e1", "adv-s38-e2-square", "adv-s38-det-gx-gy", "adv-s38-pf-mixed",
                   "adv-s38-cross-product")
GENERIC_RANKS = ("adv-s38-rank-mixed", "adv-s38-rank-mixed-low", "adv-s38-rank-minus")
EVERY_POINT = ("adv-s38-rank-top", "adv-s38-rank-normal", "adv-s38-rank-bottom")


@pytest.mark.slow   # probes that found no hole (README, round 8): about 10 s
def test_the_component_bits_read_through_power_traces_and_ranks():
    """At r = n, det(XᵀY) = ±1 read through elementary() (e₂ = e₁ on SO(3), e₂ = e₂² at n = 2) and det() of GX
    and GY with a generic G (det X = det Y) without any entry read, a Pfaffian Pf(MW'Mᵀ) = det M Pf W' and a cross
    product of the columns of M = XᵀY read at entries of ℝʳ; generic ranks of XᵀY ± I, which differ
    between the components of O(n) x O(n); ranks at every point that fail where the top block of X is singular
    (the reduced charts' normal part is onto elsewhere only), and a division by the determinant of that block
    (a rational function, true where defined).  No hole: every false statement fails under every fixed-size
    method (a generic rank false on one pair of components is refuted by exact and never passed), the true
    ones pass, det() of the n x r matrix X is refused, free proves none."""
    got = run_sizes(CHARTS)
    sizes = {c: s for (c, s) in got if s is not None}
    for c in COMPONENT_FALSE:
        assert {v for (cc, s), vs in got.items() if cc == c and s for _, v in vs} == {"fails"}, (c, got)
    for c in GENERIC_RANKS:
        v = got[(c, sizes[c])]
        assert ("exact", "fails") in v and not {x for _, x in v} & set(PASSING), (c, v)
    for c in EVERY_POINT:
        for (cc, s), v in got.items():
            if cc == c and s:    # false at some point: never passed (exact: undecided, no point where it drops)
                assert {x for _, x in v} <= {"fails", "undecided"}, (c, s, v)
    assert verdicts(got, "adv-s38-e2-e1-true", (3, 3)) <= set(PASSING)
    assert verdicts(got, "adv-s38-pf-squared-true", (2, 2)) <= set(PASSING)
    for s in ((3, 2), (4, 2)):
        assert verdicts(got, "adv-s38-div-top", s) <= set(PASSING), got
    assert verdicts(got, "adv-s38-det-x", (2, 2)) == {"error"}
    for (c, s), v in got.items():
        if s is None:
            assert {x for _, x in v} == {"undecided"}, (c, v)


UNDEFINED = "s38_undefined_residuals.py"
UNDEFINED_IDS = ("adv-s38-nan-times-zero", "adv-s38-nan-quotient", "adv-s38-nan-nonzero",
                 "adv-s38-zero-of-infinity", "adv-s38-rank-of-nan", "adv-s38-rank-of-infinity")


def test_a_residual_undefined_at_its_size_is_an_error_not_a_refutation():
    """A division by a constant that is 0 at the claim's size (tr C = 0 at r = 1): the exact method's symbolic
    arithmetic made 1/0 an infinity, and 1/0 · 0 = nan was "a nonzero function on the chart" (`fails`, no
    witness, where every sampled method is inconclusive), 1/(1/0) = 0 "vanishes identically" (a nonvanishing
    claim `fails`), a matrix [[nan]] had rank 1 and [[1/(1/0)]] rank 0 over the function field.  Closed: the
    division probe precedes every verdict of a residual that is not finite, every refutation by a rank or count
    and every verdict of a nonvanishing claim (error); a defined false claim still fails."""
    got = run_sizes(UNDEFINED, free=True)
    for c in UNDEFINED_IDS:
        v = got[(c, (3, 1))]
        assert ("exact", "error") in v, (c, v)      # auto's line names the method it chose, exact
        assert {x for _, x in v} <= {"error", "inconclusive"}, (c, v)
        assert verdicts(got, c, None, free=True) == {"undecided"}, (c, got)
    assert verdicts(got, "adv-s38-defined-false", (3, 1)) == {"fails"}


OWN_POINT = "s38_own_point_scene_read.py"


def test_a_derivative_at_the_free_scenes_own_point_keeps_the_functions_scene():
    """systems.derivative(s, F, point, tangent) moves the point handed to F, not F's scene: d/dε tr(t.Xᵀ A z_X) along
    z_X ↦ P is tr(XᵀAP).  At the dimension-free scene's own point the graph's transform (and the scene's own
    derivative) moved the scene's letters with the point: 2 tr(XᵀAP) was proved for every n, r (and at the
    coupled point), which every fixed-size method refutes at (3, 2); likewise the pairs flow
    (`systems.stiefel_pairs_flow`) of a Hamiltonian that reads t.X beside z_X took the gradient of both.  Closed:
    the transform keeps the function's scene constant there as at any point of the caller's own, and the scene's
    own derivative and pairs flow refuse a function that reads its scene's point other than through its
    argument."""
    got = run_sizes(OWN_POINT, methods=("exact", "modular", "float"), sizes=("3,2",))
    for c in ("adv-s38-own-point-scene-read-false", "adv-s38-coupled-point-scene-read-false"):
        assert verdicts(got, c, (3, 2)) == {"fails"}, (c, got)
        assert verdicts(got, c, None, free=True) == {"undecided"}, (c, got)
    assert verdicts(got, "adv-s38-own-point-scene-read", (3, 2)) <= set(PASSING), got
    assert verdicts(got, "adv-s38-own-point-scene-read", None, free=True) == {"proved"}
    # since stop 78 a flow's Hamiltonian that reads the point other than through its argument is refused when
    # traced, under every method (as the dimension-free scene refused it): systems._own_variable_only
    for c in ("adv-s38-pairs-flow-scene-read", "adv-s38-pairs-flow-scene-read-false"):
        assert verdicts(got, c, (3, 2)) == {"error"}, (c, got)
        assert verdicts(got, c, None, free=True) <= {"undecided", "error"}, (c, got)


def test_the_free_scenes_own_derivative_refuses_a_function_that_reads_its_scenes_point():
    """The scene's own route (the graph's step kept, untransformed) refuses the function that reads t.X; the
    transformed graph gives tr(XᵀAP)."""
    import pytest

    from stiefelsym import systems
    from stiefelsym.free import FreeScene
    from stiefelsym.ir import compile_claim
    from stiefelsym.ir.derivative import derivatives, scene_flows
    from stiefelsym.ir.evaluate import evaluate
    from stiefelsym.scene import REALIZATIONS

    def reads(t, z):
        return t.tr(t.X.T @ t.A @ z["X"])

    def func(s):
        return {"d": systems.derivative(s, reads, {"X": s.X, "P": s.P}, {"X": s.P}) - s.tr(s.X.T @ s.A @ s.P)}

    g = compile_claim(func, None, None, (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build))
    with pytest.raises(Exception, match="reads its scene's point"):
        evaluate(g, FreeScene(lazy=True))
    s = FreeScene(lazy=True)
    v = evaluate(derivatives(g, scene_flows(s)), s)
    assert str(s.reduce(v["d"]).normal_form) == "0"
