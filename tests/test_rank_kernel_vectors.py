"""The explicit kernel vectors a refuted rank is shown with (``_kernel_vectors`` in the exact method): each vector
is checked to be annihilated by the matrix in the exact arithmetic of its field of fractions.  The check was
sympy's ``simplify`` of every entry of M v, which took 4.4 s of a 4.5 s run on the user trial's pr_e twin at (4,1)
(s62/hidden); the check in the field is exact and takes milliseconds.  A vector that is not in the kernel is
still refused: the record then shows no vectors (the function-field rank decides the verdict either way)."""
from __future__ import annotations

import dataclasses

from sympy.polys.matrices import DomainMatrix

from stiefelsym import Rank
from stiefelsym.bases import matrix_of, so_basis
from stiefelsym.claims import load_catalog
from stiefelsym.methods.fixed_size import run_exact


def rank_of_pr_said_full(s):
    """(OD) at r = 1: ξ ↦ ξeeᵀ + eeᵀξ on so(n), e = X, has rank n − 1 (the tangent space of S^(n−1) at e); said
    to be n: false (the user trial's twin)."""
    e = s.X
    M = matrix_of(s, lambda xi: xi @ e @ e.T + e @ e.T @ xi, so_basis(s, "n"), "skew")
    return {"rank pr_e": Rank(M, int(s.n))}


def _claim(func):
    return dataclasses.replace(load_catalog().get("constraints-independent"), id="rank-xxt", func=func,
                               corrections=[], equivariance="", fails_at=None, erratum="")


def _detail(res):
    return " ".join(c.detail for c in res.checks)


def test_a_rank_below_the_printed_one_is_shown_with_checked_kernel_vectors():
    res = run_exact(_claim(rank_of_pr_said_full), 4, 1, 0)
    assert res.verdict == "fails", res
    assert "rank over the function field" in _detail(res) and "= 3 (claimed: 4)" in _detail(res), _detail(res)
    assert "explicit kernel (3 vectors, each checked M v = 0)" in _detail(res), _detail(res)


def test_a_vector_outside_the_kernel_is_not_shown(monkeypatch):
    """Negative control: the nullspace replaced by one with a vector that M does not annihilate (its first
    vector plus a unit vector) gives no kernel vectors in the record; the verdict stands on the rank."""
    original = DomainMatrix.nullspace

    def corrupted(self, *args, **kwargs):
        K = original(self, *args, **kwargs)
        rows = K.to_Matrix().tolist()
        rows[0][0] = rows[0][0] + 1
        return DomainMatrix.from_list_sympy(len(rows), len(rows[0]), rows).convert_to(K.domain)

    monkeypatch.setattr(DomainMatrix, "nullspace", corrupted)
    res = run_exact(_claim(rank_of_pr_said_full), 4, 1, 0)
    assert res.verdict == "fails", res
    assert "explicit kernel" not in _detail(res), _detail(res)
