"""A generic rank proved two-sided by the claim's own kernel vectors (``Rank(M, k, kernel=K)``).

The exact method proves M K = 0 identically in its chart and the rank d of K at an exact rational
point, so rank M <= cols − d over the function field; the rank of M at an exact point gives the
other side.  The kernel is a certificate only: a wrong one is not used (the rank is then decided
as without it), one with too few columns bounds nothing, and one that proves the rank smaller than
printed refutes the printed rank.  The example: ad_v on gl(n) at v = XXᵀ + A (symmetric, distinct
eigenvalues at a generic point) has rank n² − n, its kernel spanned by I, v, ..., v^(n−1)."""
from __future__ import annotations

import re

import pytest

from stiefelsym import Rank, admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one
from stiefelsym.methods.fixed_size import run_exact, run_points


def run_modular(claim, n, r, seed):
    return run_points(claim, n, r, "modular", seed)


def _claim(func, cid="kernel-rank"):
    return Claim(id=cid, paper=("test",), kind="dim", section="t", func=func, sizes=admissible(4))


def unit(s, a, b):
    n = s.n
    return s.mat([[s.q(1) if (i, j) == (a, b) else s.q(0) for j in range(n)] for i in range(n)])


def ad(s, v):
    """w ↦ w v − v w on gl(n), in the basis E_ab (columns) and the entries (rows)."""
    n = s.n
    cols = []
    for a in range(n):
        for b in range(n):
            C = unit(s, a, b) @ v - v @ unit(s, a, b)
            cols.append([C[i, j] for i in range(n) for j in range(n)])
    return s.mat([list(row) for row in zip(*cols)])


def vec(s, mats):
    n = s.n
    return s.mat([[M[i, j] for M in mats] for i in range(n) for j in range(n)])


def powers(s, v, k):
    out, p = [], s.In
    for _ in range(k):
        out.append(p)
        p = p @ v
    return out


def point(s):
    return s.X @ s.X.T + s.A


def right(s):
    n, v = s.n, point(s)
    return {"rank ad_v": Rank(ad(s, v), n * n - n, kernel=vec(s, powers(s, v, n)))}


SIZES = [(3, 1), (3, 2), (4, 1)]


@pytest.mark.parametrize("n,r", SIZES)
def test_the_kernel_proves_the_rank(n, r):
    res = run_exact(_claim(right), n, r, 0)
    assert res.verdict == "proved", res.message
    detail = " ".join(c.detail for c in res.checks)
    assert f"{n} kernel vectors of the claim, M K = 0 identically in the chart" in detail
    assert "two-sided" in detail


@pytest.mark.parametrize("n,r", SIZES)
def test_a_kernel_that_proves_the_rank_smaller_refutes_it(n, r):
    def f(s):
        v = point(s)
        return {"rank ad_v": Rank(ad(s, v), n * n - n + 1, kernel=vec(s, powers(s, v, n)))}
    res = run_exact(_claim(f), n, r, 0)
    detail = " ".join(c.detail for c in res.checks)
    assert res.verdict == "fails", detail
    assert f"rank <= {n * n} − {n} = {n * n - n}" in detail and "certain" in detail


def test_a_printed_rank_too_low_is_refuted_at_a_point_whatever_the_kernel():
    n, r = 3, 1

    def f(s):
        v = point(s)
        return {"rank ad_v": Rank(ad(s, v), n * n - n - 1, kernel=vec(s, powers(s, v, n)))}
    res = run_exact(_claim(f), n, r, 0)
    assert res.verdict == "fails", res.message


def test_a_wrong_kernel_vector_is_not_used():
    """v^(n−1) + A Xᵀ... is not in the kernel: the certificate is refused and the rank is decided
    without it (the function-field rank at this small size), never by the kernel."""
    n, r = 3, 1

    def f(s):
        v = point(s)
        P = powers(s, v, n)
        P[-1] = P[-1] + s.A @ s.X @ s.X.T
        return {"rank ad_v": Rank(ad(s, v), n * n - n, kernel=vec(s, P))}
    res = run_exact(_claim(f), n, r, 0)
    detail = " ".join(c.detail for c in res.checks)
    assert "of the claim, M K = 0 identically" not in detail
    assert "the kernel certificate is not one: M K is not identically 0" in detail


@pytest.mark.parametrize("columns", [
    lambda s, P: P[:-1],                                         # too few columns
    lambda s, P: P[:-1] + [P[-2]],                               # n columns, two of them equal
    lambda s, P: P[:-1] + [(s.X.T @ s.X - s.Ir)[0, 0] * P[-1]],  # a column that vanishes on T*V
], ids=["too-few", "repeated", "vanishing-on-TV"])
def test_a_kernel_of_rank_below_cols_minus_k_bounds_nothing(columns):
    """rank K = n − 1 at the points of T*V whatever the number of columns, so the bound is n² − n + 1, not
    n² − n: the certificate is not used (a column that is 0 on the constraint set counts for nothing)."""
    n, r = 3, 1

    def f(s):
        v = point(s)
        return {"rank ad_v": Rank(ad(s, v), n * n - n, kernel=vec(s, columns(s, powers(s, v, n))))}
    res = run_exact(_claim(f), n, r, 0)
    detail = " ".join(c.detail for c in res.checks)
    assert "of the claim, M K = 0 identically" not in detail
    assert f"bounds the rank by {n * n - n + 1} only" in detail


def test_a_zero_kernel_bounds_nothing():
    n, r = 3, 1

    def f(s):
        v = point(s)
        Z = s.In - s.In
        return {"rank ad_v": Rank(ad(s, v), n * n - n, kernel=vec(s, [Z] * n))}
    res = run_exact(_claim(f), n, r, 0)
    assert "of the claim, M K = 0 identically" not in " ".join(c.detail for c in res.checks)


@pytest.mark.parametrize("make,words", [
    (lambda s, M, K: Rank(M, 6, generic=False, kernel=K), "a kernel certifies a generic rank"),
    (lambda s, M, K: Rank(M, 6, kernel=K.T), "the kernel has 3 rows and the matrix 9 columns"),
    (lambda s, M, K: Rank(M, 6, kernel=[[1]]), "the kernel must be a matrix of the scene"),
    (lambda s, M, K: Rank(M, 6, kernel=s.q(1)), "the kernel must be a matrix of the scene"),
])
def test_malformed_kernels_are_refused_when_the_claim_is_traced(make, words):
    def f(s):
        v = point(s)
        return {"rank ad_v": make(s, ad(s, v), vec(s, powers(s, v, 3)))}
    for method in ("exact", "modular", "auto"):
        res = run_one(_claim(f), Size(3, 1), method, 0)
        assert res.verdict == "error", (method, res.verdict, res.message)
        assert words in res.message, res.message


def test_the_point_methods_decide_the_rank_as_without_a_kernel():
    """A kernel is the exact method's certificate: the modular method's verdict and its detail do
    not depend on it."""
    def bare(s):
        v = point(s)
        return {"rank ad_v": Rank(ad(s, v), 6)}
    a = run_modular(_claim(right), 3, 1, 0)
    b = run_modular(_claim(bare), 3, 1, 0)
    assert a.verdict == b.verdict == "checked"
    # the points differ (they are drawn from the graph's digest, which the kernel is part of)
    def words(res):
        return [re.sub(r"p = \d+", "p", c.detail) for c in res.checks]
    assert words(a) == words(b)


def test_the_mutation_analysis_changes_the_statement_not_its_certificate():
    """The nodes only the kernel reads are no mutation sites (a changed kernel leaves the statement as
    it is): the claim with a kernel offers exactly the sites of the same claim without one."""
    from collections import Counter

    from stiefelsym.ir import compile_claim
    from stiefelsym.ir.mutants import certificate_only, sites
    from stiefelsym.scene import REALIZATIONS

    def bare(s):
        v = point(s)
        return {"rank ad_v": Rank(ad(s, v), s.n * s.n - s.n)}
    cons = REALIZATIONS["standard"]
    g = compile_claim(right, 3, 1, (cons.name, cons.build))
    h = compile_claim(bare, 3, 1, (cons.name, cons.build))
    assert certificate_only(g) and not certificate_only(h)
    assert not {x.node for x in sites(g)} & certificate_only(g)

    def kinds(graph):
        return Counter((graph.ops[x.node], x.operator, x.text) for x in sites(graph))
    assert kinds(g) == kinds(h)


def stacked(s, v):
    """ad_v stacked with λ1 ad_v and λ2 ad_v: rows at two values of a parameter the kernel does not contain (the
    rows at λ2 are renamed copies of those at λ1: the exact method multiplies only one of them by K)."""
    M = ad(s, v)
    l1, l2 = s.scalar("lam1"), s.scalar("lam2")
    rows = [[M[i, j] for j in range(s.n * s.n)] for i in range(s.n * s.n)]
    return s.mat(rows + [[l1 * x for x in row] for row in rows] + [[l2 * x for x in row] for row in rows])


def test_the_kernel_of_rows_at_several_values_of_a_parameter_proves_the_rank():
    n, r = 3, 1

    def f(s):
        v = point(s)
        return {"rank": Rank(stacked(s, v), n * n - n, kernel=vec(s, powers(s, v, n)))}
    res = run_exact(_claim(f), n, r, 0)
    detail = " ".join(c.detail for c in res.checks)
    assert res.verdict == "proved", detail
    assert f"{n} kernel vectors of the claim, M K = 0 identically in the chart" in detail


def test_a_wrong_kernel_vector_of_rows_at_several_values_of_a_parameter_is_not_used():
    """The corrupted kernel of test_a_wrong_kernel_vector_is_not_used against the stacked rows: refused."""
    n, r = 3, 1

    def f(s):
        v = point(s)
        P = powers(s, v, n)
        P[-1] = P[-1] + s.A @ s.X @ s.X.T
        return {"rank": Rank(stacked(s, v), n * n - n, kernel=vec(s, P))}
    res = run_exact(_claim(f), n, r, 0)
    detail = " ".join(c.detail for c in res.checks)
    assert "of the claim, M K = 0 identically" not in detail
    assert "the kernel certificate is not one: M K is not identically 0" in detail
