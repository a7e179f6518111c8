"""examples/paper_extra.py, further statements of the paper written as a user would, verified as a
user runs them; and the two engine repairs they needed, each with a corrupted claim that is rejected:
a function handed to the scene that reads a matrix the claim built outside it (the canonical bracket,
the brackets of another realization), and the symbolic attempt of a claim the cost model never
measured, which runs in its own process so that a native abort leaves `auto` its fallback."""
from __future__ import annotations

from pathlib import Path

import pytest

from stiefelsym import claim
from stiefelsym.claims import admissible, load_claims_file
from stiefelsym.methods import fixed_size
from stiefelsym.methods.fixed_size import run_exact, run_float, run_points

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "paper_extra.py"


@pytest.fixture(scope="module")
def claims():
    return {c.id: c for c in load_claims_file(EXAMPLE)}


def test_the_example_file_states_twenty_two_claims(claims):
    assert len(claims) == 22
    assert all(c.id.startswith("x-") for c in claims.values())


#: one small size per claim (within its stated sizes), each decided by exact, modular and float
SMALL = {
    "x-euclidean-geodesic-equation": (3, 2), "x-normal-geodesic-equation": (3, 2),
    "x-submersion-right-invariant": (3, 3), "x-jensen-flow": (3, 2), "x-normal-legendre-inverse": (3, 2), "x-a-metric-manakov-on-so-n": (3, 3),
    "x-manakov-square-integrals": (3, 2), "x-big-lax-integrals-manakov-r-n": (2, 2),
    "x-potential-constant-r-n": (3, 3), "x-neumann-is-geodesic-r-n": (3, 3), "x-neumann-energy": (3, 2),
    "x-neumann-proof-constraints": (3, 2), "x-perelomov-k4": (3, 2), "x-resolvent-identity": (3, 2),
    "x-dual-trace-square": (3, 2), "x-dual-r1-determinant": (3, 1), "x-uhlenbeck-conserved": (3, 2),
    "x-uhlenbeck-involution": (3, 2), "x-uhlenbeck-coordinates": (3, 2), "x-uhlenbeck-independent-r1": (3, 1),
    "x-dual-lax-not-right-invariant": (3, 2), "x-dirac-positions-commute": (3, 2),
}


def test_every_claim_holds_at_a_small_size(claims):
    assert set(SMALL) == set(claims)
    for cid, (n, r) in SMALL.items():
        c = claims[cid]
        assert run_exact(c, n, r, 0).verdict == "proved", cid
        assert run_points(c, n, r, "modular", 0).verdict in ("checked", "proved"), cid


def test_float_decides_the_identities(claims):
    for cid in ("x-uhlenbeck-conserved", "x-dirac-positions-commute", "x-neumann-is-geodesic-r-n"):
        assert run_float(claims[cid], *SMALL[cid], 0).verdict == "numeric", cid


# -- a matrix built outside a function handed to the scene ---------------------------------------

def _captured_canonical(factor):
    def f(s):
        """{tr(UᵀX), tr(WᵀP)}₀ = tr(UᵀW) for matrices U, W built outside the functions."""
        U, W = s.fresh("n", "r"), s.fresh("n", "r")
        return {"b": s.canonical_bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.P))
                - factor * s.tr(U.T @ W)}
    return f


def _captured_metric(sign):
    def f(s):
        """{tr(UᵀX), ½tr(PᵀA⁻¹P)}_A = tr(UᵀA⁻¹P) on (cond_XP2): the flow Ẋ = A⁻¹P, read by a matrix U
        built outside the function."""
        U = s.generic("U", "n", "r")
        return {"b": s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(t.P.T @ t.Ainv @ t.P) / 2)
                - sign * s.tr(U.T @ s.Ainv @ s.P)}
    return f


CANONICAL = claim("t-captured-canonical", kind="pb", section="2", sizes=admissible(3))(_captured_canonical(1)).claim
METRIC = claim("t-captured-metric", kind="pb", section="3", realization="metric",
               sizes=admissible(3))(_captured_metric(1)).claim


def test_a_canonical_bracket_of_captured_matrices_is_decided_and_a_wrong_one_fails():
    for n, r in ((2, 1), (3, 2)):
        assert run_exact(CANONICAL, n, r, 0).verdict == "proved"
        assert run_points(CANONICAL, n, r, "modular", 0).verdict == "checked"
        assert run_float(CANONICAL, n, r, 0).verdict == "numeric"
        wrong = _captured_canonical(2)
        assert run_exact(CANONICAL, n, r, 0, func=wrong).verdict == "fails"
        assert run_points(CANONICAL, n, r, "modular", 0, func=wrong).verdict == "fails"
        assert run_float(CANONICAL, n, r, 0, func=wrong).verdict == "fails"


def _captured_scalar(factor):
    def f(s):
        """{c tr(XᵀAX), ½tr(PᵀP)}₀ = 2c tr(XᵀAP) for a number c = tr(PᵀP) computed outside the function
        (a constant of it)."""
        c = s.tr(s.P.T @ s.P)
        return {"b": s.canonical_bracket(lambda t: c * t.tr(t.X.T @ t.A @ t.X), lambda t: t.tr(t.P.T @ t.P) / 2)
                - factor * c * s.tr(s.X.T @ s.A @ s.P)}
    return f


SCALAR = claim("t-captured-scalar", kind="pb", section="2", sizes=admissible(3))(_captured_scalar(2)).claim


def test_a_number_built_outside_the_function_is_its_constant_on_every_method():
    wrong = _captured_scalar(1)
    for n, r in ((2, 1), (3, 2)):
        assert run_exact(SCALAR, n, r, 0).verdict == "proved"
        assert run_points(SCALAR, n, r, "modular", 0).verdict == "checked"
        assert run_float(SCALAR, n, r, 0).verdict == "numeric"
        assert run_exact(SCALAR, n, r, 0, func=wrong).verdict == "fails"
        assert run_points(SCALAR, n, r, "modular", 0, func=wrong).verdict == "fails"
        assert run_float(SCALAR, n, r, 0, func=wrong).verdict == "fails"


def test_a_bracket_of_another_realization_reads_captured_matrices():
    assert run_points(METRIC, 2, 1, "modular", 0).verdict == "checked"
    assert run_points(METRIC, 3, 2, "modular", 0).verdict == "checked"
    assert run_points(METRIC, 3, 2, "modular", 0, func=_captured_metric(-1)).verdict == "fails"


# -- the symbolic attempt of an unmeasured claim ---------------------------------------------------

def test_an_unmeasured_claim_isolates_its_symbolic_attempt_in_a_worker(claims):
    from stiefelsym.claims import load_catalog
    mine = claims["x-uhlenbeck-coordinates"]
    assert fixed_size.isolates(mine, 4, 3, in_worker=True)
    assert fixed_size.isolates(mine, 3, 2, in_worker=True) and not fixed_size.isolates(mine, 1, 1, in_worker=True)
    catalog = load_catalog()
    measured = catalog.get("euclidean-flow") if hasattr(catalog, "get") else catalog["euclidean-flow"]
    assert not fixed_size.isolates(measured, 4, 2, in_worker=True)


@pytest.mark.slow
def test_the_whole_file_as_a_user_runs_it():
    """Every claim at every stated size with auto and free (about 50 s on 2 shared cores)."""
    from stiefelsym import verify
    results = verify(files=[EXAMPLE], methods=("auto", "free"), jobs=1)
    assert results.ok, [str(r) for r in results if not r.expected]


def test_a_rank_of_a_list_of_rows_says_how_to_make_it_a_matrix():
    from stiefelsym import Rank

    def rows(s):
        """A Jacobian handed to Rank as it comes (a list of rows)."""
        return {"rank": Rank(s.jacobian(lambda t: [t.X.T @ t.X - t.Ir]), 1)}
    c = claim("t-rank-rows", kind="dim", section="2", sizes=admissible(2))(rows).claim
    from stiefelsym.ir import TraceRefused
    with pytest.raises(TraceRefused, match=r"s\.mat\(rows\)"):
        run_exact(c, 2, 1, 0)
    fixed = lambda s: {"rank": Rank(s.mat(s.jacobian(lambda t: [t.X.T @ t.X - t.Ir])), 1)}  # noqa: E731
    assert run_exact(c, 2, 1, 0, func=fixed).verdict == "proved"
    wrong = lambda s: {"rank": Rank(s.mat(s.jacobian(lambda t: [t.X.T @ t.X - t.Ir])), 2)}  # noqa: E731
    assert run_exact(c, 2, 1, 0, func=wrong).verdict == "fails"


# -- the characteristic polynomial without entries -------------------------------------------------

def _det_claim(shift):
    def f(s):
        """det and e_k of a 2r x 2r matrix against its entries (r = 1) and against traces."""
        from stiefelsym import block, det, elementary
        M = block([[s.X.T @ s.A @ s.P, s.X.T @ s.X], [s.P.T @ s.P, s.P.T @ s.A @ s.X]])
        e = elementary(s, M, 2)
        return {"det": det(s, M) - (M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]) - shift,
                "e_1": e[1] - s.tr(M), "e_2": 2 * e[2] - (s.tr(M) * s.tr(M) - s.tr(M @ M))}
    return f


DET = claim("t-det", kind="id", section="8", sizes=admissible(3, r_in=(1,)))(_det_claim(0)).claim


def test_det_and_elementary_agree_with_the_entries_and_a_wrong_one_fails():
    from stiefelsym.methods.dimension_free import run_free
    for n in (2, 3):
        assert run_exact(DET, n, 1, 0).verdict == "proved"
        assert run_points(DET, n, 1, "modular", 0).verdict == "checked"
        assert run_exact(DET, n, 1, 0, func=_det_claim(1)).verdict == "fails"
        assert run_float(DET, n, 1, 0, func=_det_claim(1)).verdict == "fails"
    # entries and the size need coordinates: the dimension-free method leaves it to the fixed sizes
    assert run_free(DET).verdict == "undecided"


def test_the_dual_spectral_coefficients_are_proved_for_every_n_and_r(claims):
    from stiefelsym.methods.dimension_free import run_free
    assert run_free(claims["x-dual-trace-square"]).verdict == "proved"


def test_elementary_refuses_a_size_that_is_not_an_integer():
    from stiefelsym import elementary
    with pytest.raises(ValueError, match="integer k >= 0"):
        elementary(None, None, -1)
    with pytest.raises(ValueError, match="integer k >= 0"):
        elementary(None, None, 1.5)
