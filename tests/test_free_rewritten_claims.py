"""Claims rewritten so that the dimension-free method proves them (a determinant of 1×1 products written as
their Gram determinant, …): each is proved with a certificate the independent checker accepts, keeps its
fixed-size verdicts, and a corrupted version is neither proved dimension-free nor passes at a fixed size."""

import pytest

from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.proofs import sec8_dual_lax_pair as sec8

CATALOG = load_catalog()


def _proved(res):
    assert res.verdict == "proved", res.message
    report = check_certificate(res.certificate_data)
    assert report.accepted, report.message
    return res


@pytest.mark.parametrize("cid", ["poisson-sphere-chasles"])
def test_the_rewritten_claim_is_proved_dimension_free(cid):
    _proved(run_free(CATALOG.get(cid)))


def tangency_with_the_wrong_mixed_sign(s):
    """Corrupted: (e, Re)(p, Rp) + (e, Rp)(p, Re) in place of the Gram determinant (not conserved)."""
    flow = s.dirac_flow(sec8.H_poisson_sphere)

    def F(t):
        e, p, R = t.X, t.P, t.resolvent(t.lam)
        return (e.T @ R @ e) @ (p.T @ R @ p) + (e.T @ R @ p) @ (p.T @ R @ e)
    return {"d det(U^T R U)/dt": s.d(F, flow)}


def velocity_with_the_wrong_sign(s):
    """Corrupted: Aė = (A⁻¹e, e)p + (A⁻¹e, p)e."""
    flow = s.dirac_flow(sec8.H_poisson_sphere)
    e, p, Ai = s.X, s.P, s.Ainv
    return {"A de/dt": s.A @ flow.Xdot - p @ (e.T @ Ai @ e) - e @ (e.T @ Ai @ p)}


CORRUPTED = [("poisson-sphere-chasles", tangency_with_the_wrong_mixed_sign),
             ("poisson-sphere-chasles", velocity_with_the_wrong_sign)]


@pytest.mark.parametrize("cid, func", CORRUPTED, ids=[f.__name__ for _, f in CORRUPTED])
def test_a_corrupted_rewritten_claim_is_not_proved_and_fails_at_a_fixed_size(cid, func):
    c = CATALOG.get(cid)
    assert run_free(c, func).verdict != "proved"
    assert run_exact(c, 3, 1, 0, func=func).verdict == "fails"
