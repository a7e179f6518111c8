"""examples/paper_extra2.py, more statements of the paper (Appendices 1 and 2, §10's F_λ, §3's Jensen
family) as a user writes and runs them: each holds at a small size under the exact and the modular
method, each false variant is refuted (a `not` claim proved nonzero, a wrong sign failing with a
witness), and a false variant stated too widely is caught where it actually holds."""
from __future__ import annotations

from pathlib import Path

import pytest

from stiefelsym.claims import load_claims_file
from stiefelsym.methods.fixed_size import run_exact, run_float, run_points

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "paper_extra2.py"


@pytest.fixture(scope="module")
def claims():
    return {c.id: c for c in load_claims_file(EXAMPLE)}


#: one small size per claim (within its stated sizes)
SMALL = {
    "y-double-energy": (3, 2), "y-double-energy-wrong-sign": (3, 2), "y-double-spectral-invariants": (2, 1),
    "y-double-velocity-lambda": (3, 2), "y-coupled-r1-metrics-coincide": (3, 1),
    "y-coupled-diagonal-is-neumann": (2, 1), "y-coupled-energy": (2, 1),
    "y-coupled-single-momentum-not-conserved": (2, 2), "y-f-lambda-partial-fractions": (3, 2),
    "y-f-lambda-wrong-sign": (3, 2), "y-magnetic-energy": (3, 2), "y-magnetic-geodesic-phi-eps": (3, 2),
    "y-magnetic-geodesic-phi-not-conserved": (3, 2), "y-jensen-family-commutes": (3, 2),
    "y-euclidean-normal-differ": (3, 2), "y-cpb-central-integrals": (3, 2),
    "y-neumann-normal-through-theta": (3, 2), "y-complex-energy": (2, 1),
    "y-complex-lagrangian-not-conserved": (2, 1), "y-ym-projections": (3, 1),
    "y-ym-half-projection-not-skew": (3, 1), "y-constraints-independent": (2, 1),
    "y-constraints-rank-wrong": (2, 2),
}
FALSE = {"y-double-energy-wrong-sign", "y-coupled-single-momentum-not-conserved",
         "y-magnetic-geodesic-phi-not-conserved", "y-euclidean-normal-differ", "y-complex-lagrangian-not-conserved",
         "y-ym-half-projection-not-skew"}


def test_the_example_file_states_twenty_three_claims(claims):
    assert set(claims) == set(SMALL)
    assert {cid for cid, c in claims.items() if c.expect == "nonzero"} == FALSE


def test_every_statement_is_decided_as_expected_at_a_small_size(claims):
    for cid, (n, r) in SMALL.items():
        c = claims[cid]
        if cid in ("y-f-lambda-wrong-sign", "y-constraints-rank-wrong"):
            expected = {"fails"}
        else:
            expected = {"proved"}
        assert run_exact(c, n, r, 0).verdict in expected, cid
        if c.kind != "dim":
            assert run_points(c, n, r, "modular", 0).verdict in expected | {"checked"}, cid


def test_a_false_variant_where_it_holds_is_not_passed_as_refuted(claims):
    """T − U of the double system is conserved at r = n (tr XᵀAY = tr A there), and the magnetic torque
    vanishes on V(2, 2) (e₁∧e₂ = det(X)J): the `not` claims, run there, must not be `proved`."""
    for cid, size in (("y-double-energy-wrong-sign", (2, 2)), ("y-magnetic-geodesic-phi-not-conserved", (2, 2))):
        c = claims[cid]
        assert run_exact(c, *size, 0).verdict == "fails", cid


def test_the_float_method_decides_the_identities(claims):
    for cid in ("y-double-energy", "y-magnetic-energy", "y-coupled-energy", "y-cpb-central-integrals"):
        assert run_float(claims[cid], *SMALL[cid], 0).verdict == "numeric", cid
    assert run_float(claims["y-f-lambda-wrong-sign"], 3, 2, 0).verdict == "fails"


def test_the_free_method_proves_the_energies_for_every_n_and_r(claims):
    from stiefelsym.methods.dimension_free import run_free
    for cid in ("y-double-energy", "y-coupled-energy", "y-magnetic-energy", "y-neumann-normal-through-theta"):
        assert run_free(claims[cid]).verdict == "proved", cid
    # the trace of a word of the complex letters without a canonical cyclic form: named, and left to the sizes
    res = run_free(claims["y-complex-energy"])
    assert res.verdict == "undecided" and "has no canonical normal form" in res.message, res.message
    # a false variant is never proved by rewriting: it needs a witness
    assert run_free(claims["y-coupled-single-momentum-not-conserved"]).verdict == "undecided"


def test_a_rank_at_every_point_without_a_constant_minor_is_undecided_not_refuted():
    """The Jacobian of (cond_XP) has rank r(r + 1) at every point of T*V (a regular level set), but none of
    its maximal minors is constant: the exact method must not call the true statement false (it did, with
    no witness); it is undecided, and the right inverse of the example proves it."""
    from stiefelsym import Rank, claim as claim_
    from stiefelsym.claims import admissible as adm

    def every_point(s):
        """rank r(r + 1) of the constraints' Jacobian at every point."""
        J = s.mat(s.jacobian(lambda t: [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]))
        return {"rank": Rank(J, s.r * (s.r + 1), generic=False)}
    c = claim_("t-every-point-constraints", kind="dim", section="2", sizes=adm(3))(every_point).claim
    for n, r in ((2, 1), (3, 1)):
        res = run_exact(c, n, r, 0)
        assert res.verdict == "undecided" and "not decided" in res.message, (n, r, res.verdict, res.message)
    # a rank at every point that is wrong over the function field is still refuted
    low = lambda s: {"rank": Rank(s.mat(s.jacobian(lambda t: [t.X.T @ t.X - t.Ir])), 2, generic=False)}  # noqa: E731
    assert run_exact(c, 2, 1, 0, func=low).verdict == "fails"


@pytest.mark.slow
def test_the_whole_file_as_a_user_runs_it():
    from stiefelsym import verify
    results = verify(files=[EXAMPLE], methods=("auto",), jobs=1)
    assert results.ok, [str(r) for r in results if not r.expected]
