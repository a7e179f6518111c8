"""s.generic(name, "n-r", ...): a generic block on ℝⁿ⁻ʳ, the second block of the chart at X₀ = (E₁ … E_r) that the
paper's proofs write (P₀ = (P₁; P₂) with P₂ an (n − r) × r matrix, in (ddim), LEMA1, NEUMANN2, (P-neutral)).
ℝⁿ⁻ʳ is an opaque coordinate space (never ℝⁿ or ℝʳ), its size the number n − r: such a claim needs fixed sizes, its
records are never shared across r, and every fixed-size method decides it."""
from __future__ import annotations

import pytest

from stiefelsym import admissible, block
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one, shared_size


def _claim(func, cid):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func,
                 sizes=admissible(4, where=lambda n, r: r < n))


def _tangent_at_x0(s):
    """P₀ = (η; P₂) is tangent at X₀ = (I_r; 0): X₀ᵀP₀ + P₀ᵀX₀ = 0."""
    P2 = s.generic("P2", "n-r", "r")
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    P0 = block([[s.eta], [P2]])
    return {"X0ᵀP0 + P0ᵀX0": X0.T @ P0 + P0.T @ X0}


def _gram_vanishes(s):
    """P₂ᵀP₂ = 0 (false)."""
    P2 = s.generic("P2", "n-r", "r")
    return {"P2ᵀP2": P2.T @ P2}


def _trace_of_a_symmetric_block(s):
    """tr G = 0 for a generic symmetric (n − r) × (n − r) block (false; its graph names no ℝʳ)."""
    return {"tr G": s.tr(s.generic("G", "n-r", "n-r", "sym"))}


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float", "auto"])
def test_a_true_statement_on_the_blocks_at_x0_holds(method):
    res = run_one(_claim(_tangent_at_x0, "t-tangent"), Size(4, 2), method, seed=0)
    assert res.verdict in ("proved", "checked", "numeric"), res.line()


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float", "ball", "auto"])
@pytest.mark.parametrize("func", [_gram_vanishes, _trace_of_a_symmetric_block])
def test_a_false_statement_on_the_blocks_fails(method, func):
    res = run_one(_claim(func, "t-false"), Size(4, 1), method, seed=0)
    assert res.verdict == "fails", res.line()


def test_a_block_on_r_n_minus_r_is_never_shared_across_r():
    c = _claim(_trace_of_a_symmetric_block, "t-shared")
    assert shared_size(c, Size(4, 2)) is None and shared_size(c, Size(4, 3)) is None


def test_the_dimension_free_method_leaves_it_to_fixed_sizes():
    res = run_one(_claim(_tangent_at_x0, "t-free"), None, "free", seed=0)
    assert res.verdict == "undecided" and "n − r" in res.message, res.line()


def test_r_n_minus_r_is_not_r_n():
    """A block (r, n − r) is no matrix on ℝⁿ: multiplied with X it is refused, with the same words everywhere."""
    def mixed(s):
        B = block([[s.zeros(s.r, s.r, ("r", "r"))], [s.generic("P2", "n-r", "r")]])
        return {"XᵀB": s.X.T @ B}
    for method in ("exact", "modular", "float"):
        res = run_one(_claim(mixed, "t-mixed"), Size(3, 1), method, seed=0)
        assert res.verdict == "error" and "do not match" in res.message, res.line()
