"""The trace of a product that no other node reads is computed from the product's diagonal.

The evaluator fuses tr(x @ y) when the product x @ y is read by the trace alone (not the output,
not a traced function's body, not another node), on the exact method's polynomial backend: the
trace of a power M^k, computed as M^(k-1) M, needs m of the last product's m^2 entries, which are
the largest polynomials of the chain (the spectral invariants of the 2r x 2r dual Lax matrix,
whose Newton sums read tr L^(2r)).  The fused value is the same rational function, so verdicts,
residuals and witnesses do not change; a corrupted power trace is still refuted.
"""
from __future__ import annotations

import numpy as np
import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim
from stiefelsym.ir.evaluate import _trace_products
from stiefelsym.methods.fixed_size import run_exact, run_points


def _claim(func, cid="trace-product"):
    return Claim(id=cid, paper=("test",), kind="id", section="t", func=func, sizes=admissible(4))


def lax(s):
    """A Lax matrix of the Neumann type, λΦ + XXᵀ − λ²A (n × n), with the resolvent's λ."""
    return s.lam * s.Phi + s.X @ s.X.T - s.lam * s.lam * s.A


def powers_commute(s):
    """tr(L^k M) = tr(M L^k) for L = λΦ + XXᵀ − λ²A, M = Aλ + XXᵀ: both sides are fused traces."""
    L, M = lax(s), s.A + s.X @ s.X.T
    L3 = L @ L @ L
    return {"tr(L^3 M) - tr(M L^3)": s.tr(L3 @ M) - s.tr(M @ L3)}


def power_trace_vs_entries(s):
    """tr(L (L L)) (a fused trace) is the sum of the diagonal entries of (L L) L computed whole."""
    L = lax(s)
    P = L @ L @ L
    diag = s.q(0)
    for i in range(s.n):
        diag = diag + P[i, i]
    return {"tr(L (L L)) - sum of the diagonal of (L L) L": s.tr(L @ (L @ L)) - diag}


def power_trace_off_by_a_term(s):
    """False: tr(L^3) with a term of the product's off-diagonal added."""
    L = lax(s)
    P = L @ L @ L
    return {"tr(L^3) - (tr(L^3) + (L^3)_12)": s.tr(L @ L @ L) - (s.tr(P) + P[0, 1])}


def power_trace_scaled(s):
    """False: tr(L^2 L) against 2 tr(L^3) (the fused trace must not vanish)."""
    L = lax(s)
    return {"tr(L^2 L) - 2 tr(L L^2)": s.tr((L @ L) @ L) - s.tr(L @ (L @ L)) * 2}


@pytest.mark.parametrize("n,r", [(3, 1), (3, 2), (4, 2)])
def test_a_fused_trace_equals_the_sum_of_the_product_s_diagonal(n, r):
    assert run_exact(_claim(power_trace_vs_entries), n, r, 0).verdict == "proved"
    assert run_exact(_claim(powers_commute), n, r, 0).verdict == "proved"


@pytest.mark.parametrize("func", [power_trace_off_by_a_term, power_trace_scaled])
def test_a_corrupted_power_trace_is_refuted_by_every_method(func):
    c = _claim(func, "trace-product-false")
    assert run_exact(c, 3, 2, 0).verdict == "fails"
    assert run_points(c, 3, 2, "modular", 0).verdict == "fails"
    assert run_points(c, 3, 2, "rational", 0).verdict == "fails"


def test_only_a_product_read_by_the_trace_alone_is_fused():
    """In power_trace_vs_entries the product (L L) L is read entry by entry (not fused) and L (L L)
    by the trace alone (fused); in powers_commute the products L^3 M and M L^3 are each read once."""
    from stiefelsym.ir import compile_claim
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS["standard"]
    for func, fused in ((power_trace_vs_entries, 1), (powers_commute, 2)):
        g = compile_claim(func, 3, 2, (cons.name, cons.build))
        from stiefelsym.ir.evaluate import _deps
        assert len(_trace_products(g, _deps(g))) == fused, func.__name__


def test_the_backend_s_fused_trace_is_the_trace_of_the_product():
    """PolyBackend.trace_matmul against trace(matmul) on matrices of polynomials with denominators."""
    from stiefelsym.backends.polyfield import SymbolicField
    from stiefelsym.scene import Scene
    f = SymbolicField()
    s = Scene(3, 2, f, chart="cayley")
    L = s.lam * s.Phi + s.X @ s.X.T - s.lam * s.lam * s.A
    R = s.resolvent(s.lam)
    for x, y in ((L, L @ L), (R, L), (s.X.T @ R, L @ s.X), (s.X, s.X.T)):
        a = x._trace_product(y)
        b = (x @ y)._trace()
        assert a == b
    assert np.shape(s.X._trace_product(s.X.T) - s.tr(s.X @ s.X.T)) == ()


def test_the_fused_trace_of_symmetric_or_skew_factors_sums_each_pair_once():
    """tr(a b) is summed over the upper triangle and doubled when a and bᵀ are both symmetric or both skew,
    and is the diagonal's alone when one is symmetric and the other skew; a factor that is symmetric but
    for one entry is summed in full (every comparison is exact)."""
    from stiefelsym.backends.polyfield import SymbolicField
    from stiefelsym.scene import Scene
    f = SymbolicField()
    s = Scene(3, 2, f, chart="cayley")
    S1 = s.A + s.X @ s.X.T
    S2 = s.lam * s.A @ s.A + s.P @ s.P.T
    K1, K2 = s.Phi, s.lam * s.Phi @ s.A + s.A @ s.Phi * s.lam
    E = s.mat([[s.q(1) if (i, j) == (0, 1) else s.q(0) for j in range(3)] for i in range(3)], ("n", "n"))
    for x, y in ((S1, S2), (K1, K2), (S1, K1), (K2, S2), (S1 + E, S2), (K1, K2 + E), (S2, S2 @ S2)):
        assert x._trace_product(y) == (x @ y)._trace()
    assert S1._trace_product(K1) == s.q(0)
