"""A traced function whose body is a long chain (a sum over a basis at n = 7 has thousands of nodes)
is evaluated without recursion, by every method; a false statement built the same way fails."""
from __future__ import annotations

import pytest

from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.run.runner import run_one

DEPTH = 1500        # well beyond Python's recursion limit of 1000 frames


def long_sum(t):
    acc = t.tr(t.P.T @ t.P)
    for k in range(1, DEPTH):
        acc = acc + t.q(1, k + 1) * t.tr(t.P.T @ t.P)
    return acc


def potential(t):
    return t.tr(t.X.T @ t.A @ t.X)


def deep_true(s):
    return {"{F, F}": s.bracket(long_sum, long_sum)}


def deep_false(s):
    return {"{F, H}": s.bracket(long_sum, potential)}


@pytest.mark.parametrize("method", ["exact", "rational", "modular", "float"])
def test_a_long_chain_in_a_function_body(method):
    true = Claim(id="deep-true", paper=(), kind="pb", section="test", func=deep_true, sizes=admissible(3))
    false = Claim(id="deep-false", paper=(), kind="pb", section="test", func=deep_false, sizes=admissible(3))
    assert run_one(true, Size(3, 2), method, 0).verdict in ("proved", "checked", "numeric")
    assert run_one(false, Size(3, 2), method, 0).verdict == "fails"
