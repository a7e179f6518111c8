"""The Manakov flows are checked for B = A^k with the operator 𝔸_k(ξ) = Σ_{m<k} A^m ξ A^{k−1−m}
(proofs/sec4_integrability.py): negative controls.  A wrong polynomial operator is refuted against the
printed entries (Manakov), and a Lax pair whose 𝓐 does not match its B, or a B outside the span of the
powers' operators, is refuted under the exact method (products only, on the equivariant chart) and
under the modular method."""
from __future__ import annotations

import pytest

from stiefelsym import admissible, comm
from stiefelsym.claims import Claim
from stiefelsym.methods.fixed_size import run_exact, run_points
from stiefelsym.proofs import sec4_integrability as sec4


def _claim(func, cid):
    return Claim(id=cid, paper=("test",), kind="id", section="t", func=func, sizes=admissible(5))


def operator_one_power_short(s):
    """False: Σ_{m<k} A^m ξ A^{k−m} (one power of A too many on the right) against the entries of B = A^2."""
    squares = [a * a for a in s.a]
    wrong = s.xi @ s.A @ s.A + s.A @ s.xi @ s.A
    return {"entries - polynomial": sec4.manakov_operator(s, squares)(s.xi) - wrong}


def lax_with_the_next_power(s):
    """False: the flow of 𝔸_2 with 𝓐 = 𝔸_2(Φ) + λA³ (the B of the operator is A²)."""
    flow = s.dirac_flow(sec4.H_manakov_power(2))
    L = s.Phi + s.lam * s.A
    M = sec4.manakov_power_operator(s, 2)(s.Phi) + s.lam * s.A @ s.A @ s.A
    return {"Lax": s.d(lambda t: t.Phi + t.lam * t.A, flow) - comm(M, L)}


def lax_of_a_non_manakov_operator(s):
    """False: ξ ↦ A ξ A, not a Manakov operator (its entries a_i a_j ξ_ij are not (b_i − b_j)/(a_i − a_j) ξ_ij),
    with 𝓐 = AΦA + λA²."""
    def H(t):
        return t.killing(t.A @ t.Phi @ t.A, t.Phi) / 2
    flow = s.dirac_flow(H)
    L = s.Phi + s.lam * s.A
    M = s.A @ s.Phi @ s.A + s.lam * s.A @ s.A
    return {"Lax": s.d(lambda t: t.Phi + t.lam * t.A, flow) - comm(M, L)}


@pytest.mark.parametrize("func", [operator_one_power_short, lax_with_the_next_power, lax_of_a_non_manakov_operator])
def test_a_wrong_manakov_operator_or_partner_is_refuted(func):
    c = _claim(func, "manakov-powers-false")
    assert run_exact(c, 4, 2, 0).verdict == "fails"
    assert run_points(c, 4, 2, "modular", 0).verdict == "fails"


def test_the_catalog_s_manakov_lax_is_proved_by_products_at_5_2():
    from stiefelsym.claims import load_catalog
    res = run_exact(load_catalog().get("manakov-lax"), 5, 2, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any(x.startswith("equivariance") for x in res.reductions), res.reductions
