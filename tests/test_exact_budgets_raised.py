"""The symbolic budgets raised where the exact proof became cheap (the normal part [0; Z2] of the
charts, the reduced unitary Cayley point on the symbolic Cayley chart): at the new sizes the exact
method proves the claim, and a corrupted claim of each class moved is refuted exactly there.

Classes: the second point (Y, Q) on the equivariant chart (the coupled Lax pairs, n = 2, 3); the
complex point on the Cayley chart (the complex Neumann system, n = 2, 3); the coordinate readers on
the reduced Cayley chart (the Manakov reflections, n = 3)."""
from __future__ import annotations

import pytest

import stiefelsym.proofs.app2_double_coupled_complex as a
import stiefelsym.proofs.sec4_integrability as m
from stiefelsym import admissible, twisted
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.methods.fixed_size import run_exact


def _claim(func, cid="t-raised"):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7))


def _coupled_dual_lax_wrong_diagonal(s):
    """(LA3*C) with D2 = YᵀQ + I_r: the identity added to a diagonal block of 𝓐(λ) (XᵀP alone is 0 for r = 1)."""
    return {"LA3*C": a.dual_coupled_residual(s, a.H_coupled(a.NORMAL),
                                             lambda t, z: (z["X"].T @ z["P"], z["Y"].T @ z["Q"] + t.Ir))}


def _reflections_forget_S_on_P(s):
    """The reflection S₁ applied to X alone in the image of the flow: dP/dt of (S X, S P) against dP/dt."""
    V = m.flow_XP3(s)
    S = twisted.reflection(s)
    W = m.flow_XP3_at(s, S @ s.X, S @ s.P)
    return {"S: dP/dt": W["P"] - V["P"]}


@pytest.mark.parametrize("n,r", [(2, 2), (3, 1)])
def test_the_coupled_dual_lax_pair_is_proved_and_a_wrong_diagonal_refuted(n, r):
    c = load_catalog().get("coupled-dual-lax")
    assert c.exact_at(n, r)
    assert run_exact(c, n, r, 0).verdict == "proved"
    res = run_exact(_claim(_coupled_dual_lax_wrong_diagonal), n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert any("second point (Y, Q)" in d for d in res.reductions), res.reductions


@pytest.mark.parametrize("n,r", [(2, 1), (3, 1)])
def test_the_complex_dual_lax_pair_corrected_is_proved_and_the_printed_one_refuted(n, r):
    c = load_catalog().get("complex-neumann-dual-lax")
    corr = c.corrections[0]
    assert (n, r) in {(2, 1), (2, 2), (3, 1)} and dict(corr.exact_max_r).get(n, 0) >= r
    res = run_exact(c, n, r, 0, corr.func)
    assert res.verdict == "proved", (res.verdict, res.message)
    # the equivariant chart (the derivative step's value is a block matrix of whole copies of R^n and
    # R^r, no splitting of R^n), with the complex point's reduced unitary Cayley transform
    assert any("unitary Cayley transform" in d and "X = X0" in d for d in res.reductions), res.reductions
    if n == 2:
        assert run_exact(c, n, r, 0).verdict == "fails"        # (I_n − λA)⁻¹ as printed


def test_the_complex_momenta_are_proved_on_the_cayley_chart():
    c = load_catalog().get("complex-neumann-momenta")
    assert c.exact_at(3, 1)
    res = run_exact(c, 3, 1, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any("unitary Cayley transform" in d for d in res.reductions), res.reductions


@pytest.mark.parametrize("n,r", [(3, 2), (3, 3)])
def test_the_manakov_reflections_are_proved_and_a_forgotten_reflection_refuted(n, r):
    c = load_catalog().get("manakov-reflections")
    assert c.exact_at(n, r)
    assert run_exact(c, n, r, 0).verdict == "proved"
    res = run_exact(_claim(_reflections_forget_S_on_P), n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)


def _same_component_read_entrywise(s):
    """det(XᵀY) = 1 (r = n = 2), with an entry of X read (the Cayley chart): true only when X and Y
    lie on one component of O(n)."""
    M = s.X.T @ s.Y
    return {"det(X^T Y) - 1": M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0] - s.q(1) + (s.X[0, 0] - s.X[0, 0])}


def test_the_cayley_chart_puts_the_second_point_on_either_component():
    res = run_exact(_claim(_same_component_read_entrywise), 2, 2, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert any("A = diag(a)" in d and "component 2 of O(n) for Y" in d for d in res.reductions), res.reductions
    assert len(res.reductions) == 4


def _noether_of_the_whole_phi(s):
    """(singular-a-noether) with XᵀDX in place of the block DΦD (at r = n, XXᵀ = I and the whole of Φ
    is conserved): not conserved."""
    import stiefelsym.proofs.sec6_compatible_brackets as p
    D = twisted.eigenspace_projector(s)
    return {"d(X^T D X)/dt": s.d(lambda t: t.X.T @ D @ t.X, s.dirac_flow(p.H_neum_eigenspace))}


def _manakov_lax_wrong_b(s):
    """(manakov-lax) with 𝓐 = 𝔸(Φ) + λA (B replaced by A): not a Lax partner."""
    flow = s.dirac_flow(m.H_manakov)
    L = s.Phi + s.lam * s.A
    M = m.manakov_operator(s, m.b_eigenvalues(s))(s.Phi) + s.lam * s.A
    return {"Lax": s.d(lambda t: t.Phi + t.lam * t.A, flow) - (M @ L - L @ M)}


def test_the_corank_budget_names_the_sizes_with_r_close_to_n():
    c = _claim(_reflections_forget_S_on_P)
    import dataclasses
    c0 = dataclasses.replace(c, exact_max_n=3, exact_corank=((6, 0), (7, 0)))
    assert c0.exact_at(7, 7) and c0.exact_at(3, 1) and not c0.exact_at(7, 6) and not c0.exact_at(5, 5)
    assert c0.exact_budget_text() == "n <= 3; r = n at n = 6, 7"
    c1 = dataclasses.replace(c0, exact_corank=((7, 1),))
    assert c1.exact_at(7, 6) and not c1.exact_at(7, 5) and not c1.exact_at(6, 6)
    assert c1.exact_budget_text() == "n <= 3; n - r <= 1 at n = 7"
    for bad in (((7, -1),), ((7, 7),), ((7, 0.5),)):
        with pytest.raises(ValueError, match="exact_corank"):
            dataclasses.replace(c0, exact_corank=bad)


@pytest.mark.parametrize("cid,n,r", [("manakov-reflections", 7, 7), ("dual-lax-reflections", 5, 4),
                                     ("dual-lax-reflections", 5, 5), ("singular-a-noether", 6, 6),
                                     ("manakov-lax", 5, 5)])
def test_the_claims_raised_to_r_n_are_proved_there_and_a_corrupted_claim_refuted(cid, n, r):
    c = load_catalog().get(cid)
    assert c.exact_at(n, r)
    res = run_exact(c, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any("acting on the right" in d for d in res.reductions), res.reductions
    bad = run_exact(_claim(_reflections_forget_S_on_P if "reflections" in cid else
                           _noether_of_the_whole_phi if "noether" in cid else _manakov_lax_wrong_b), n, r, 0)
    assert bad.verdict == "fails", (bad.verdict, bad.message)


# -- dimension statements whose function-field rank is cheap at a few more sizes (measured: well under a
# second each), and chasles-cones-real at (4,1) ------------------------------------------------------

def _shifted(claim, by):
    """The claim with every generic Rank's expected value moved by ``by`` (a wrong printed dimension)."""
    import dataclasses

    from stiefelsym.ir.statements import Rank

    def func(s):
        out = claim.func(s)
        return {k: dataclasses.replace(v, expected=v.expected + by) if isinstance(v, Rank) else v
                for k, v in out.items()}
    func.__doc__ = claim.func.__doc__
    return dataclasses.replace(claim, id=f"t-{claim.id}-{by:+d}", func=func, corrections=[])


@pytest.mark.parametrize("cid,n,r", [("com-completeness", 4, 1), ("pencil-l5-l6", 7, 2),
                                     pytest.param("pencil-kernel-ker-a2", 4, 2, marks=pytest.mark.slow),
                                     pytest.param("neumann2-kernel", 4, 3, marks=pytest.mark.slow),
                                     pytest.param("cif-completeness", 4, 2, marks=pytest.mark.slow),
                                     pytest.param("casimirs-complete-on-leaf", 4, 1, marks=pytest.mark.slow)])
def test_a_raised_dimension_is_proved_two_sided_and_a_wrong_one_refuted(cid, n, r):
    c = load_catalog().get(cid)
    assert c.exact_at(n, r)
    res = run_exact(c, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    for by in (-1, 1):      # one below: a rank at a point refutes it; one above: the function-field rank does
        bad = run_exact(_shifted(c, by), n, r, 0)
        assert bad.verdict == "fails", (by, bad.verdict, bad.message)


def test_the_chasles_cones_are_proved_at_4_1_and_a_wrong_sign_refuted():
    import stiefelsym.proofs.sec8_dual_lax_pair as d

    c = load_catalog().get("chasles-cones-real")
    assert c.exact_at(4, 1)
    assert run_exact(c, 4, 1, 0).verdict == "proved"

    def plus_pp(s):
        """λ^r𝓘_{2r}(λ) against det(λI − Q(A + PPᵀ)Q): the sign of PPᵀ flipped."""
        Q = s.In - s.X @ s.X.T
        M = Q @ (s.A + s.P @ s.P.T) @ Q
        integrals, _ = d.spectral_integrals(s, s.lam)
        return {"charpoly": s.lam * integrals[s.r] - d.det_matrix(s, s.scalar_matrix(s.lam, s.n, "n") - M)}
    res = run_exact(_claim(plus_pp), 4, 1, 0)
    assert res.verdict == "fails", (res.verdict, res.message)


# -- three Manakov claims one size past their former budget (measured on the equivariant chart: manakov-lax at
# (7, 2) 3-5 s, manakov-dual-integrals at (6, 1) 2 s, dual-invariants-manakov-r-n at (5, 5) 6-12 s) -----------

def _manakov_j2_and_potential(s):
    """(manakov-dual-integrals) with tr(XᵀAX) added to 𝒥_2(λ): not conserved by the Manakov flow (B = A²)."""
    import stiefelsym.proofs.sec7_grassmannians as g
    import stiefelsym.proofs.sec8_dual_lax_pair as d

    def F(t):
        return g.column(t, [d.manakov_coefficients(t, t.lam)[2] + t.tr(t.X.T @ t.A @ t.X)])
    return {"d(J_2 + tr X^T A X)/dt": s.d(F, s.dirac_flow(m.H_manakov_power(2)))}


def _manakov_a_phi_a_phi(s):
    """tr(AΦAΦ) said to be conserved by the Manakov flow with B = A² (only 4 tr(A²Φ²) + 2 tr(AΦAΦ) is)."""
    return {"d tr(A Phi A Phi)/dt": s.d(lambda t: t.tr(t.A @ t.Phi @ t.A @ t.Phi), s.dirac_flow(m.H_manakov_power(2)))}


@pytest.mark.slow
@pytest.mark.parametrize("cid,n,r,wrong", [("manakov-lax", 7, 2, _manakov_lax_wrong_b),
                                           ("manakov-dual-integrals", 6, 1, _manakov_j2_and_potential),
                                           ("dual-invariants-manakov-r-n", 5, 5, _manakov_a_phi_a_phi)])
def test_the_manakov_claims_raised_are_proved_and_a_corrupted_function_refuted(cid, n, r, wrong):
    c = load_catalog().get(cid)
    assert c.exact_at(n, r)
    res = run_exact(c, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    bad = run_exact(c, n, r, 0, func=wrong)
    assert bad.verdict == "fails", (bad.verdict, bad.message)


# -- gen-chasles2 at (4, 2): the products of its 4 x 4 tangency determinant over (a_i − λ) cancel on their
# factors (PolyRing.cancel_product; measured 6.8 s -> 0.6 s of CPU) -------------------------------------

def _tangency_against_the_plane_of_p_and_x(s):
    """The tangency determinant of 𝒱(XB, PB) against that of 𝒱(P, X) (X and P swapped): not equal."""
    import stiefelsym.proofs.sec8_dual_lax_pair as g
    B, cone = g.rotation(s), g.cone_matrix(s, s.lam)
    VB, V = g.plane_VV(s, s.X @ B, s.P @ B), g.plane_VV(s, s.P, s.X)
    return {"tangency": g.det(s, g.entries(VB.T @ cone @ VB)) - g.det(s, g.entries(V.T @ cone @ V))}


def test_gen_chasles2_is_proved_at_4_2_and_the_plane_of_p_and_x_refuted():
    c = load_catalog().get("gen-chasles2")
    assert c.exact_at(4, 2)
    res = run_exact(c, 4, 2, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    bad = run_exact(_claim(_tangency_against_the_plane_of_p_and_x), 4, 2, 0)
    assert bad.verdict == "fails", (bad.verdict, bad.message)
