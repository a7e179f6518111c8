"""The kernel certificates of the §6 dimension lemmas (proofs/sec6_dimension_lemmas.py): the exact method
proves the generic ranks two-sided with the claims' kernel vectors (Casimir gradients, the solutions of
(L1), (L2), the limits of the pencil's Casimirs), and a corrupted kernel (a wrong vector, a dropped
column) is never the route to ``proved``."""
from __future__ import annotations

import pytest

from stiefelsym import Rank
from stiefelsym.claims import load_catalog
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.proofs.sec6_dimension_lemmas import (
    a2_system, a2_system_kernel, as_columns, generic_leaf_rank, gl_coords, kernel_generic_lambda1, lambda1,
    leaf_printed, theta, unit)

ROUTE = "of the claim, M K = 0 identically in the chart"


def details(res):
    return {c.name: c.detail for c in res.checks}


@pytest.fixture(scope="module")
def catalog():
    return load_catalog()


@pytest.mark.parametrize("cid,n,r,names", [
    ("pencil-leaves-singular", 3, 2, ["rank Λ₁ at a generic point of gl(n)"]),
    ("pencil-rank-a1", 3, 2, ["rank Lambda_{1,-1}", "rank Lambda_2", "rank Lambda_1 + t Lambda_2",
                              "rank of (L3), (L4)"]),
    ("pencil-a2-generic", 3, 2, ["rank Lambda1(h+v)", "(A2)"]),
])
def test_the_kernel_proves_the_rank(catalog, cid, n, r, names):
    res = run_exact(catalog.get(cid), n, r, 0)
    assert res.verdict == "proved", res.message
    d = details(res)
    for name in names:
        assert ROUTE in d[name] and "two-sided" in d[name], d[name]


def casimir_columns(s, y, last_plus=None, drop_last=False):
    """The columns (0, (y + yᵀ)^k), k = 0..n−1, of :func:`kernel_generic_lambda1`, corrupted on demand:
    ``last_plus`` (ξ, η) added to the last column, or the last column dropped."""
    n = s.n
    zero = s.zeros(n, n, ("n", "n"))
    pairs, p = [], s.In
    for _ in range(n):
        pairs.append((zero, p))
        p = p @ (y + y.T)
    if last_plus is not None:
        xi, eta = last_plus(s, y)
        pairs[-1] = (pairs[-1][0] + xi, pairs[-1][1] + eta)
    if drop_last:
        pairs = pairs[:-1]
    return as_columns(s, [gl_coords(s, xi, eta) for xi, eta in pairs])


def leaves_with(kernel):
    def f(s):
        y = s.generic("Y", "n", "n")
        return {"rank": Rank(lambda1(s, y), generic_leaf_rank(s.n), kernel=kernel(s, y))}
    return f


def test_the_helper_is_the_kernel_the_corruptions_start_from(catalog):
    res = run_exact(catalog.get("pencil-leaves-singular"), 3, 1, 0, func=leaves_with(kernel_generic_lambda1))
    assert res.verdict == "proved" and ROUTE in details(res)["rank"], res.message
    res = run_exact(catalog.get("pencil-leaves-singular"), 3, 1, 0, func=leaves_with(casimir_columns))
    assert res.verdict == "proved" and ROUTE in details(res)["rank"], res.message


@pytest.mark.parametrize("corruption,words", [
    # v^(n−1) + I would still be a kernel vector (I = v^0 is one): the wrong vectors add h = y − yᵀ or E_00
    (dict(last_plus=lambda s, y: (y - y.T, s.In - s.In)), "the kernel certificate is not one: M K is not identically 0"),
    (dict(last_plus=lambda s, y: (s.In - s.In, unit(s, s.n, s.n, 0, 0, ("n", "n")))),
     "the kernel certificate is not one: M K is not identically 0"),
    (dict(drop_last=True), "bounds the rank by"),
])
def test_a_corrupted_casimir_kernel_is_not_the_route(catalog, corruption, words):
    """(h, v^(n−1)) and (0, v^(n−1) + E_00) are not in ker Λ1 (wrong vectors); without v^(n−1) the kernel
    bounds the rank by n² − n + 1 only."""
    kernel = leaves_with(lambda s, y: casimir_columns(s, y, **corruption))
    res = run_exact(catalog.get("pencil-leaves-singular"), 3, 1, 0, func=kernel)
    d = details(res)["rank"]
    assert ROUTE not in d and words in d, d


def a2_with(corrupt):
    def f(s):
        n, r = s.n, s.r
        x = theta(s)
        K = a2_system_kernel(s, x, s.A)
        rows, cols = K.shape
        entries = [[K[i, j] for j in range(cols)] for i in range(rows)]
        corrupt(s, entries)
        return {"(A2)": Rank(a2_system(s, x, s.A), n * n - n + leaf_printed(n, r), kernel=s.mat(entries))}
    return f


def swap_first_orders(s, entries):
    """The first limit vector (z, y) = (w(0), w'(0)) with y replaced by z: Λ_{1,−1}z = Λ1 z fails."""
    half = len(entries) // 2
    for i in range(half):
        entries[half + i][0] = entries[i][0]


def drop_a_limit_vector(s, entries):
    """The last of the n limit vectors (z, y) replaced by the zero column."""
    n = s.n
    for row in entries:
        row[n - 1] = s.q(0)


@pytest.mark.parametrize("corrupt,words", [
    (swap_first_orders, "the kernel certificate is not one: M K is not identically 0"),
    (drop_a_limit_vector, "bounds the rank by"),
])
def test_a_corrupted_a2_kernel_is_not_the_route(catalog, corrupt, words):
    res = run_exact(catalog.get("pencil-a2-generic"), 3, 2, 0, func=a2_with(corrupt))
    d = details(res)["(A2)"]
    assert ROUTE not in d and words in d, d
