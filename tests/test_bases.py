"""stiefelsym.bases: the bases of so(m), Sym(m) and the matrix spaces, and the matrix of a linear map in them, used
in claims the way a user writes them (tests/claims_bases.py): the true ranks are proved, the false twins fail, the
dimension-free method leaves them undecided, and misuse is an error with a message."""
from __future__ import annotations

from pathlib import Path

import pytest

from stiefelsym import Rank, admissible
from stiefelsym.bases import coordinates, matrix_of, matrix_units, so_basis, sym_basis
from stiefelsym.claims import Claim, Size, load_claims_file
from stiefelsym.run.runner import run_one

HERE = Path(__file__).resolve().parent


@pytest.fixture(scope="module")
def claims():
    return {c.id: c for c in load_claims_file(HERE / "claims_bases.py")}


TRUE = ("bases-action-rank", "bases-tangent-rank", "bases-sandwich-rank", "bases-ad-rank")
FALSE = ("bases-action-rank-plus-one", "bases-ad-rank-full", "bases-zero-map-full-rank")


@pytest.mark.parametrize("size", [(3, 1), (4, 2), (3, 3)])
@pytest.mark.parametrize("cid", TRUE)
def test_the_true_ranks_are_proved(claims, cid, size):
    res = run_one(claims[cid], Size(*size), "exact", 0)
    assert res.verdict == "proved", (cid, size, res.message)


@pytest.mark.parametrize("size", [(3, 1), (3, 3)])
@pytest.mark.parametrize("cid", FALSE)
def test_the_false_twins_fail_under_exact(claims, cid, size):
    res = run_one(claims[cid], Size(*size), "exact", 0)
    assert res.verdict == "fails", (cid, size, res.message)


@pytest.mark.parametrize("method", ["modular", "rational", "float", "auto"])
@pytest.mark.parametrize("cid", FALSE)
def test_the_false_twins_pass_under_no_method(claims, cid, method):
    res = run_one(claims[cid], Size(3, 2), method, 0)
    assert res.verdict not in ("proved", "checked", "numeric"), (cid, method, res.verdict, res.message)


@pytest.mark.parametrize("cid", TRUE + FALSE)
def test_the_dimension_free_method_leaves_them_undecided(claims, cid):
    res = run_one(claims[cid], None, "free", 0)
    assert res.verdict == "undecided", (cid, res.verdict, res.message)
    assert "size (n) used as a number" in res.message or "fixed" in res.message


def _claim(cid, kind, func, n, r):
    return Claim(id=cid, paper=("toy",), kind=kind, section="", func=func,
                 sizes=admissible(n_min=n, n_max=n, r_min=r, r_max=r))


def test_the_bases_at_a_size():
    """Counts, shapes, orthonormality for <a, b> = -tr(ab)/2 (so) and tr(aᵀb) (units), evaluated on an exact scene."""
    out = {}

    def shapes(s):
        so, sym, units = so_basis(s, "n"), sym_basis(s, "r"), matrix_units(s, "n", "r")
        out["counts"] = (len(so), len(sym), len(units))
        # orthonormality of so(4) for the paper's form, and of the units for tr(aᵀb): Gram matrices minus I
        gram_so = s.mat([[s.killing(a, b) for b in so] for a in so])
        gram_units = s.mat([[s.tr(a.T @ b) for b in units] for a in units])
        skew = [a + a.T for a in so]
        symm = [a - a.T for a in sym]
        return {"so Gram": gram_so - s.identity(len(so)), "units Gram": gram_units - s.identity(len(units)),
                "skew": skew[0] + skew[-1], "sym": symm[0] + symm[-1]}
    res = run_one(_claim("bases-shapes", "id", shapes, 4, 2), Size(4, 2), "exact", 0)
    assert res.verdict == "proved", res.message
    assert out["counts"] == (6, 3, 8)


def test_misuse_is_an_error_with_a_message():
    def bad_space(s):
        return {"x": so_basis(s, "m")[0]}

    def empty(s):
        return {"rank": Rank(matrix_of(s, lambda e: e, so_basis(s, "r")), 0)}

    def bad_kind(s):
        return {"x": s.mat([coordinates(s.X, "skew")])}

    for cid, kind, func, size, words in (("bases-bad-space", "id", bad_space, (3, 1), "'n' or 'r'"),
                                         ("bases-empty", "dim", empty, (2, 1), "empty"),
                                         ("bases-bad-kind", "id", bad_kind, (3, 2), "square")):
        res = run_one(_claim(cid, kind, func, *size), Size(*size), "exact", 0)
        assert res.verdict == "error", (cid, res.verdict, res.message)
        assert words in res.message, (cid, res.message)


def test_a_full_rank_beyond_the_symbolic_budget_is_proved_at_exact_points(claims):
    """At (7,7) the Cayley chart needs a symbolic 7x7 solve, beyond the exact method's budget: a claim whose every
    check is a generic rank of full size is then proved at exact rational points (a nonzero maximal minor on each
    component of O(7)), as the rational method proves it.  The negative controls: a rank above the full size fails,
    and a zero map said to be of full rank is not proved."""
    res = run_one(claims["bases-action-rank"], Size(7, 7), "exact", 0)
    assert res.verdict == "proved" and "beyond budget" in res.reductions[0], (res.verdict, res.message)
    assert "each of the 2 components" in res.certificate
    assert run_one(claims["bases-action-rank-plus-one"], Size(7, 7), "exact", 0).verdict == "fails"
    zero = run_one(claims["bases-zero-map-full-rank"], Size(7, 7), "exact", 0)
    assert zero.verdict not in ("proved", "checked", "numeric"), (zero.verdict, zero.message)
    assert run_one(claims["bases-zero-map-full-rank"], Size(3, 2), "exact", 0).verdict == "fails"


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float", "auto"])
def test_a_skew_image_read_in_sym_coordinates_is_not_given_the_rank_of_sym(claims, method):
    """Own attempt to fool the new coordinates: ξ ↦ XᵀξX (image so(r)) in "sym" coordinates, said to have rank
    dim Sym(r).  No method passes it: exact and auto refute it (the rows' linear relations bound the rank by
    r(r−1)/2), the point methods find rank 1 at their points and stay inconclusive (a point bounds from below)."""
    res = run_one(claims["bases-skew-image-in-sym-coordinates"], Size(3, 2), method, 0)
    assert res.verdict not in ("proved", "checked", "numeric"), (method, res.verdict, res.message)


def test_a_rational_refutation_the_symbolic_chart_contradicts_is_an_error(claims, monkeypatch):
    """The guard of the exact method's pre-check: were the rational point to refute a claim whose symbolic residual
    on the Cayley chart is identically 0 (two evaluations of one graph disagreeing: an engine defect), the verdict is
    `error`, never `proved` or `fails`.  Simulated by a pre-check that refutes a true column norm read by entries."""
    from stiefelsym.methods import fixed_size
    from stiefelsym.results import Result

    def column_norm(s):       # reads entries of X on R^n: the symbolic Cayley chart, after the pre-check
        return {"gram": sum(s.X[i, 0] * s.X[i, 0] for i in range(int(s.n))) - 1}
    assert run_one(_claim("bases-column-norm", "id", column_norm, 3, 2), Size(3, 2), "exact", 0).verdict == "proved"
    true = _claim("bases-column-norm", "id", column_norm, 3, 2)     # a claim of its own (no plan of the first run)

    def forged(claim, n, r, seed, func, graph):
        res = Result(claim=claim.id, paper=[], section="", kind="id", title="", statement="", n=n, r=r,
                     method="rational", verdict="fails", expected=False, seconds=0.0, seed=seed)
        res.witness = {"entry": "gram", "value": "1"}
        return res
    from stiefelsym.ir import seal
    monkeypatch.setattr(fixed_size, "_refuting_point", forged)
    seal._STATE.update(modules=None, print=None)   # the test's own change of the engine (conftest resets it too)
    res = run_one(true, Size(3, 2), "exact", 0)
    assert res.verdict == "error" and "disagree" in res.message, (res.verdict, res.message)


def test_a_size_times_zero_in_a_false_claim_fails():
    """Negative control of a size times 0 or a negative int as a number: X·(0·n) = X and X·(−n) = X·n are false."""
    def zero(s):
        return {"r": s.X * (s.n * 0) - s.X}

    def minus(s):
        return {"r": s.X * (s.n * -1) - s.X * s.n}
    for cid, func in (("bases-n-times-zero", zero), ("bases-n-times-minus-one", minus)):
        for method in ("exact", "modular"):
            res = run_one(_claim(cid, "id", func, 3, 2), Size(3, 2), method, 0)
            assert res.verdict == "fails", (cid, method, res.verdict, res.message)
