"""The kernel certificates of the catalog's dimension claims (``Rank(M, k, kernel=K)``): the centralizer
of Φ for the rank of ad_Φ (Lemma 2l), the solutions of (L1), (L2) at Ψ = 0 for the rank of Λ1
(Theorem NEUMANN2).  The catalog claims are proved two-sided by their kernels; the same matrices with a
corrupted kernel (a vector that is not in the kernel, a column dropped) are not proved by the kernel
route (the certificate is refused or bounds too little, and the rank is decided as without it)."""
from __future__ import annotations

import dataclasses

import pytest

from stiefelsym import Rank, comm
from stiefelsym.claims import load_catalog
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.proofs import sec2_hamiltonian_flows as sec2
from stiefelsym.proofs import sec7_grassmannians as sec7
from stiefelsym.proofs.sec6_dimension_lemmas import lambda1

KERNEL_ROUTE = "of the claim, M K = 0 identically in the chart"


def detail(res):
    return " ".join(c.detail for c in res.checks)


def _claim(func, cid):
    """The catalog claim with another function: its reviewed reason of equivariance (the chart X = X0)
    applied to the statement with another kernel."""
    return dataclasses.replace(load_catalog().get(cid), func=func, corrections=[])


@pytest.mark.parametrize("cid,n,r", [("adjoint-orbit-dimension", 4, 1), ("adjoint-orbit-dimension", 4, 2),
                                     ("neumann2-kernel", 3, 1)])
def test_the_catalog_kernel_proves_the_rank(cid, n, r):
    """At (4, 1) the kernel of ad_Φ needs so(ker Φ) (n > 2r + 1), at (4, 2) the odd powers of Φ alone."""
    res = run_exact(load_catalog().get(cid), n, r, 0)
    assert res.verdict == "proved", res.message
    assert KERNEL_ROUTE in detail(res) and "two-sided" in detail(res), detail(res)


# -- ad_Φ at (4, 1): Φ and so(ker Φ) = Q so(4) Q --------------------------------------------------------

def ad_rank(kernel):
    def f(s):
        return {"2l": Rank(sec2.ad_matrix(s, s.Phi), sec2.two_l_printed(s.n, s.r), kernel=kernel(s))}
    return _claim(f, "adjoint-orbit-dimension")


def ad_kernel_vectors(s):
    Q = sec2.annihilator_of_point(s)
    return [sec2.so_coordinates(s.Phi)] + [sec2.so_coordinates(Q @ e @ Q) for e in sec2.wedge_basis(s, s.n)]


def test_ad_phi_the_kernel_as_written_here_is_the_catalogs():
    res = run_exact(ad_rank(lambda s: sec2.kernel_matrix(s, ad_kernel_vectors(s))), 4, 1, 0)
    assert res.verdict == "proved" and KERNEL_ROUTE in detail(res), detail(res)


def test_ad_phi_a_vector_outside_the_centralizer_is_refused():
    """AΦ + ΦA (skew, but it does not commute with Φ) in the place of Φ."""
    def kernel(s):
        v = ad_kernel_vectors(s)
        v[0] = sec2.so_coordinates(s.A @ s.Phi + s.Phi @ s.A)
        return sec2.kernel_matrix(s, v)
    res = run_exact(ad_rank(kernel), 4, 1, 0)
    assert KERNEL_ROUTE not in detail(res)
    assert "the kernel certificate is not one: M K is not identically 0" in detail(res)


def test_ad_phi_the_kernel_without_phi_bounds_too_little():
    """so(ker Φ) alone (Φ dropped) has rank 1 of the 2 the printed rank needs."""
    res = run_exact(ad_rank(lambda s: sec2.kernel_matrix(s, ad_kernel_vectors(s)[1:])), 4, 1, 0)
    assert KERNEL_ROUTE not in detail(res)
    assert "the kernel certificate bounds the rank by 5 only" in detail(res), detail(res)


# -- Λ1 at Ψ = 0, (3, 1): gl(1) ⊕ gl(2) --------------------------------------------------------------

def lambda1_rank(kernel):
    def f(s):
        n, r, X = s.n, s.r, s.X
        P0 = sec7.horizontal(s, X, s.P)
        h = P0 @ X.T - X @ P0.T
        return {"rank": Rank(lambda1(s, h + X @ X.T), 2 * r * (n - r), kernel=kernel(s, X, h))}
    return _claim(f, "neumann2-kernel")


def test_lambda1_the_kernel_as_written_here_is_the_catalogs():
    res = run_exact(lambda1_rank(sec7.lema1_kernel_at_psi_zero), 3, 1, 0)
    assert res.verdict == "proved" and KERNEL_ROUTE in detail(res), detail(res)


def lema1_kernel_sign_flipped(s, X, h):
    """sec7.lema1_kernel_at_psi_zero with η = π'Cπ + πCπ' in the place of π'Cπ − πCπ' ((L2) fails)."""
    n, r = s.n, s.r
    pi = X @ X.T
    pi_perp = s.In - pi
    xis = [X @ w @ X.T for w in sec7.skew_units(s, r, ("r", "r"))]
    xis += [pi_perp @ w @ pi_perp for w in sec7.skew_units(s, n, ("n", "n"))]
    etas = [X @ w @ X.T for w in sec7.sym_units(s, r, ("r", "r"))]
    etas += [pi_perp @ w @ pi_perp for w in sec7.sym_units(s, n, ("n", "n"))]
    vectors = [sec7.gl_coordinates(xi, pi_perp @ comm(h, xi) @ pi + pi @ comm(h, xi) @ pi_perp) for xi in xis]
    vectors += [sec7.gl_coordinates(s.zeros(n, n, ("n", "n")), eta) for eta in etas]
    return s.mat([list(row) for row in zip(*vectors)])


def test_lambda1_a_sign_flipped_in_L2_is_refused():
    res = run_exact(lambda1_rank(lema1_kernel_sign_flipped), 3, 1, 0)
    assert KERNEL_ROUTE not in detail(res)
    assert "the kernel certificate is not one: M K is not identically 0" in detail(res)


def test_lambda1_the_kernel_without_sym_r_bounds_too_little():
    """Without the column XσXᵀ (σ ∈ Sym(1)), the vectors span gl(n − r) ⊕ so(r) only."""
    def kernel(s, X, h):
        K = sec7.lema1_kernel_at_psi_zero(s, X, h)
        r, n = s.r, s.n
        first_sym = r * (r - 1) // 2 + n * (n - 1) // 2           # the columns: ξ-vectors, then the η-vectors
        cols = [j for j in range(K.shape[1]) if j != first_sym]
        return s.mat([[K[i, j] for j in cols] for i in range(K.shape[0])])
    res = run_exact(lambda1_rank(kernel), 3, 1, 0)
    assert KERNEL_ROUTE not in detail(res)
    assert "the kernel certificate bounds the rank by 5 only" in detail(res), detail(res)
