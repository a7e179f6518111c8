"""Dimension claims proved exactly at n = 6, 7: the symbolic budget of the dimension claims whose
certificate stays cheap there is raised, and a matrix of rational numbers has its rank computed
over Q by flint (the same at every point, both sides at once).  At each new size the claim as
printed is proved, and a corrupted rank (one more, one less) is refuted exactly: by the
function-field rank or the rank at an exact point for a generic matrix, by the rank over Q for a
constant one (the ranks of ad_Phi, of the invariants' differentials on the fibre, of Λ1 on Ψ⁻¹(0), and
the invariance conditions of the quadratic forms)."""
from __future__ import annotations

import dataclasses

import pytest

import stiefelsym.proofs.sec2_hamiltonian_flows as h
import stiefelsym.proofs.sec3_geodesic_flows as g
import stiefelsym.proofs.sec7_grassmannians as s7
from stiefelsym import Rank
from stiefelsym.claims import load_catalog
from stiefelsym.methods.fixed_size import run_exact


def _corrupted(cid: str, func):
    """The catalog claim with another function: the same reviewed reason of equivariance, applied to
    a statement that is false."""
    c = load_catalog().get(cid)
    return dataclasses.replace(c, func=func, corrections=[])


def _ad_phi_off_by(k: int):
    def claim(s):
        """2l + k in place of 2l."""
        return {"rank ad_Phi": Rank(h.ad_matrix(s, s.Phi), h.two_l_printed(s.n, s.r) + k, generic=True)}
    return claim


def _invariant_forms_off_by(k: int):
    def claim(s):
        """One invariant quadratic form more or fewer than printed."""
        rows, unknowns, _ = g._fibre_action_matrix(s)
        span = 1 if s.r in (1, s.n) else 2
        return {"invariant forms": Rank(g._conditions_matrix(s, rows, unknowns), unknowns - span + k,
                                        generic=False)}
    return claim


def _ddim_off_by(k: int):
    def claim(s):
        """ddim + k independent invariants on the fibre."""
        out = h.psi_and_gram_give_ddim_functions(s)["rank on the fibre"]
        return {"rank on the fibre": Rank(out.matrix, out.expected + k, generic=True)}
    return claim


@pytest.mark.parametrize("cid,n,r", [("constraints-independent", 7, 4), ("invariants-complete", 7, 3),
                                     ("invariants-differential-dimension", 6, 5), ("invariant-metrics", 6, 3),
                                     ("adjoint-orbit-dimension", 7, 2), ("invariant-tori-dimensions", 6, 2),
                                     ("neumann2-kernel", 7, 6)])
def test_the_raised_dimension_claims_are_proved_at_n_6_7(cid, n, r):
    c = load_catalog().get(cid)
    assert c.exact_at(n, r)
    res = run_exact(c, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)


@pytest.mark.parametrize("n,r", [(6, 4), (7, 4)])
def test_the_printed_invariant_metrics_fail_exactly_where_the_pfaffian_is_invariant(n, r):
    c = load_catalog().get("invariant-metrics")
    res = run_exact(c, n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert "matrix of rational numbers" in str(res.checks)


@pytest.mark.parametrize("k", [1, -1])
def test_a_constant_rank_off_by_one_is_refuted_over_q(k):
    res = run_exact(_corrupted("invariant-metrics", _invariant_forms_off_by(k)), 7, 3, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert "exact rank" in str(res.checks) and "over Q" in str(res.checks)


@pytest.mark.parametrize("k", [1, -1])
def test_a_rank_of_ad_phi_off_by_one_is_refuted_at_n_7(k):
    res = run_exact(_corrupted("adjoint-orbit-dimension", _ad_phi_off_by(k)), 7, 2, 0)
    assert res.verdict == "fails", (res.verdict, res.message)


@pytest.mark.parametrize("k", [1, -1])
def test_a_ddim_off_by_one_is_refuted_at_n_7(k):
    res = run_exact(_corrupted("invariants-complete", _ddim_off_by(k)), 7, 3, 0)
    assert res.verdict == "fails", (res.verdict, res.message)


def _neumann2_kernel_off_by(k: int):
    def claim(s):
        """The rank of Λ1(h + v) on Ψ⁻¹(0) one more or one less than printed."""
        R = s7.neumann2_kernel(s)["rank Lambda1(h+v) at Psi = 0"]
        return {"rank": Rank(R.matrix, R.expected + k, generic=True)}
    return claim


@pytest.mark.parametrize("n,r,k", [(5, 2, 1), (7, 6, -1)])
def test_a_rank_of_lambda1_on_psi_zero_off_by_one_is_refuted_at_the_new_sizes(n, r, k):
    c = load_catalog().get("neumann2-kernel")
    assert c.exact_at(n, r)
    res = run_exact(_corrupted("neumann2-kernel", _neumann2_kernel_off_by(k)), n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
