"""The equivariant chart of the standard realization: A11 and A22 diagonal (the stabilizer of X0,
with O(r) acting on the right), the resolvent through a small dense core, and negative controls
that read coordinates of R^r or use what only the reduced chart makes true."""
from __future__ import annotations

import pytest

import stiefelsym.proofs.sec8_dual_lax_pair as sec8
from stiefelsym import admissible, block
from stiefelsym.claims import Claim, Size
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.run.runner import run_one
from stiefelsym.proofs.sec5_neumann import H_neumann_normal
from stiefelsym.scene import Scene


def _claim(id: str, func) -> Claim:
    return Claim(id=id, paper=(), kind="id", section="t", func=func, sizes=admissible(7))


def _dual_lax(s, corrupt: bool = False):
    """d𝓛*/dt − [𝓛*, 𝓐*] of Theorem DUAL along the Neumann flow (κ = 0); ``corrupt``: the block
    Λ − λI of 𝓐* with λ replaced by 2λ."""
    A_dual = sec8.A_dual_normal
    if corrupt:
        def A_dual(t):
            return block([[t.X.T @ t.P, t.Ir],
                          [sec8.Lambda(t) - t.scalar_matrix(t.lam * 2, t.r, "r"), -(t.P.T @ t.X)]])
    return {"LA3": sec8.dual_lax_residual(s, H_neumann_normal, A_dual)}


def test_chart_has_diagonal_blocks_and_states_them():
    s = Scene(6, 2, SymbolicField(), chart="equivariant", right_reduction=True)
    A = s.A._a
    assert all(A[i, j] == 0 for i in range(6) for j in range(6) if i != j and (i >= 2 and j >= 2 or i < 2 and j < 2))
    assert A[0, 3] != 0 and A[0, 0] != 0
    assert "A11 (r x r) and A22 ((n - r) x (n - r)) diagonal" in s.equivariant_reduction()
    t = Scene(6, 2, SymbolicField(), chart="equivariant")
    assert t.A._a[0, 1] != 0 and t.A._a[2, 3] == 0
    assert "A22 ((n - r) x (n - r)) diagonal" in t.equivariant_reduction()


@pytest.mark.parametrize("n,r", [(6, 2), (6, 5)])
def test_dual_lax_pair_proved_through_a_6x6_resolvent_and_a_corruption_fails(n, r):
    good = _claim("dual", _dual_lax)
    res = run_one(good, Size(n, r), "exact", 0)
    assert res.verdict == "proved", res.message
    assert any("A11 (r x r) and A22" in d for d in res.reductions), res.reductions
    bad = _claim("dual-bad", lambda s: _dual_lax(s, corrupt=True))
    assert run_one(bad, Size(n, r), "exact", 0).verdict == "fails"


def _offdiag_r(s):
    return s.mat([[0, 1] + [0] * (s.r - 2)] + [[0] * s.r for _ in range(s.r - 1)], ("r", "r"))


ADVERSARIAL = {
    # each vanishes on the reduced chart (A11 diagonal) but not on T*V
    "typed constant on R^r": lambda s: {"x": s.tr(_offdiag_r(s) @ s.X.T @ s.A @ s.X)},
    "untyped constant": lambda s: {"x": s.tr(s.mat([[0, 1] + [0] * (s.r - 2)] + [[0] * s.r for _ in range(s.r - 1)])
                                             @ s.X.T @ s.A @ s.X)},
    "entry of an r x r matrix": lambda s: {"x": (s.X.T @ s.A @ s.X)[0, 1]},
    "generic r x r parameters entrywise": lambda s: {"x": (s.X.T @ s.A @ s.X)[1, 0] * s.tr(s.eta @ s.eta)},
}


@pytest.mark.parametrize("what", sorted(ADVERSARIAL))
@pytest.mark.parametrize("method", ["exact", "auto"])
def test_claims_that_read_R_r_are_not_proved_on_the_reduced_chart(what, method):
    res = run_one(_claim("adv", ADVERSARIAL[what]), Size(4, 2), method, 0)
    assert res.verdict == "fails", (what, res.verdict, res.message)


def test_a_claim_true_on_every_point_that_reads_R_r_falls_back_to_O_n():
    """An entry of XᵀX − I (zero on V) read through R^r: the O(n) chart alone proves it, and says so."""
    res = run_one(_claim("xtx", lambda s: {"x": (s.X.T @ s.X - s.Ir)[0, 1]}), Size(5, 2), "exact", 0)
    assert res.verdict == "proved", res.message
    assert not any("A11 (r x r)" in d for d in res.reductions), res.reductions
