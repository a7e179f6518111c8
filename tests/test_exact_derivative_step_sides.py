"""The derivative step of the double, coupled and complex systems (``systems.derivative(s, F, z, v)``)
is shaped like F's value: a block matrix of whole copies of R^n (the so(n, n) pair, a realified
complex matrix) or of R^r (the dual pairs) differentiated by that step is no splitting of R^n, so the
claims that do so go to the exact method's equivariant chart (X = X0, A generic with A22 diagonal,
the second point (Y, Q) generic), where their resolvents are one symbolic inverse of lambda I - A.

Negative controls at the sizes the symbolic budget now includes: a corrupted diagonal of the coupled
dual pair, the printed so(n, n) pair and the printed (LA3*D) fail exactly; a true splitting of R^n
inside a differentiated function is still recorded as a coordinate read."""
from __future__ import annotations

import pytest

import stiefelsym.proofs.app2_double_coupled_complex as a
from stiefelsym import admissible, block, comm
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.ir import compile_claim
from stiefelsym.ir.passes import BLOCK_SPLITTING, coordinate_reads
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.scene import REALIZATIONS
from stiefelsym.systems import coupled_point, derivative


def _claim(func, cid="t-step-sides"):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7))


def _graph(func, n, r):
    cons = REALIZATIONS["standard"]
    return compile_claim(func, n, r, (cons.name, cons.build))


def _coupled_dual_lax_wrong_diagonal(s):
    """(LA3*C) with D2 = YᵀQ + I_r: the identity added to a diagonal block of 𝓐(λ)."""
    return {"LA3*C": a.dual_coupled_residual(s, a.H_coupled(a.NORMAL),
                                             lambda t, z: (z["X"].T @ z["P"], z["Y"].T @ z["Q"] + t.Ir))}


def _splitting_inside_the_step(s):
    """A times d/dt of [Y^T Y; 0_(n-r) x r] along the coupled flow: its blocks split R^n into
    R^r and n - r coordinates (read through the derivative step's value)."""
    z = coupled_point(s)
    n, r = s.n, s.r
    F = lambda t, w: block([[w["Y"].T @ w["Y"]], [t.zeros(n - r, r, ("?", "r"))]])
    return {"A d/dt[Y^T Y; 0]": s.A @ derivative(s, F, z, a.coupled_flow(s, a.H_coupled(a.NORMAL)))}


@pytest.mark.parametrize("cid", ["coupled-dual-lax", "coupled-perturbed-dual-lax", "coupled-big-lax-normal",
                                 "coupled-perturbed-big-lax", "double-neumann-dual-lax", "complex-neumann-dual-lax"])
def test_a_differentiated_block_matrix_of_whole_spaces_reads_no_coordinates(cid):
    c = load_catalog().get(cid)
    for func in [c.func] + [k.func for k in c.corrections]:
        assert BLOCK_SPLITTING not in coordinate_reads(_graph(func, 3, 2))


def test_a_splitting_of_R_n_inside_a_differentiated_function_is_still_read():
    assert BLOCK_SPLITTING in coordinate_reads(_graph(_splitting_inside_the_step, 4, 2))
    res = run_exact(_claim(_splitting_inside_the_step), 3, 1, 0)
    assert not any("X = X0" in d for d in res.reductions), res.reductions


@pytest.mark.parametrize("n,r", [(3, 2), (3, 3)])
def test_the_coupled_dual_lax_pair_is_proved_on_the_equivariant_chart_and_a_wrong_diagonal_refuted(n, r):
    c = load_catalog().get("coupled-dual-lax")
    assert c.exact_at(n, r)
    res = run_exact(c, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any("X = X0" in d and "second point (Y, Q)" in d for d in res.reductions), res.reductions
    bad = run_exact(_claim(_coupled_dual_lax_wrong_diagonal), n, r, 0)
    assert bad.verdict == "fails", (bad.verdict, bad.message)
    assert any("X = X0" in d for d in bad.reductions), bad.reductions


@pytest.mark.parametrize("cid", ["coupled-big-lax-normal", "coupled-perturbed-big-lax",
                                 pytest.param("double-neumann-dual-lax", marks=pytest.mark.slow)])
def test_the_printed_pair_fails_and_its_correction_is_proved_at_3_2(cid):
    c = load_catalog().get(cid)
    corr = c.corrections[0]
    assert dict(corr.exact_max_r).get(3, 0) >= 2
    printed = run_exact(c, 3, 2, 0)
    assert printed.verdict == "fails", (printed.verdict, printed.message)
    assert printed.witness, printed.certificate
    fixed = run_exact(c, 3, 2, 0, corr.func)
    assert fixed.verdict == "proved", (fixed.verdict, fixed.message)
    assert any("X = X0" in d for d in fixed.reductions), fixed.reductions



def _double_corrected_commutator_swapped(s):
    """The corrected (LA3*D) with the commutator's operands swapped: dL/dt = [A, L]."""
    z = a.double_point(s)
    L = lambda t, w: a.L_dual_double(t, w, t.resolvent(t.lam))
    return {"LA3*D": derivative(s, L, z, a.flow_double(s, z)) - comm(a.A_dual_double(s, z), L(s, z))}


def test_at_the_largest_new_r_1_size_the_printed_so_n_n_pair_fails_exactly_and_its_correction_is_proved():
    c = load_catalog().get("coupled-big-lax-normal")
    corr = c.corrections[0]
    assert dict(corr.exact_max_r).get(7, 0) >= 1
    assert run_exact(c, 7, 1, 0).verdict == "fails"
    fixed = run_exact(c, 7, 1, 0, corr.func)
    assert fixed.verdict == "proved", (fixed.verdict, fixed.message)
    assert any("X = X0" in d for d in fixed.reductions), fixed.reductions


@pytest.mark.slow   # an exact proof at (5,2): about 40 s
def test_at_5_2_the_corrected_double_pair_is_proved_and_a_swapped_commutator_refuted():
    c = load_catalog().get("double-neumann-dual-lax")
    corr = c.corrections[0]
    assert dict(corr.exact_max_r).get(5, 0) >= 2
    assert run_exact(c, 5, 2, 0, corr.func).verdict == "proved"
    bad = run_exact(_claim(_double_corrected_commutator_swapped), 5, 2, 0)
    assert bad.verdict == "fails", (bad.verdict, bad.message)
    assert any("X = X0" in d for d in bad.reductions), bad.reductions


def _entry_after_the_step(s):
    """Entry (0, 0) of d/dε [X; X] along P, read after the derivative step: P₁₁, 0 on the equivariant chart
    (P = (W; Z), W skew) and nonzero elsewhere: false."""
    d = derivative(s, lambda t, w: block([[w["X"]], [w["X"]]]), {"X": s.X, "P": s.P}, {"X": s.P})
    return {"e": s.mat([[d[0, 0]]])}


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_an_entry_of_the_steps_value_read_after_it_is_a_coordinate_read(n, r):
    """The step's value is shaped like its function's (whole copies of R^n), and an entry read of it is read
    like any other: the claim leaves the equivariant chart and is refuted exactly."""
    res = run_exact(_claim(_entry_after_the_step), n, r, 0)
    assert res.verdict == "fails" and not any("X = X0" in d for d in res.reductions), (res.verdict, res.reductions)
