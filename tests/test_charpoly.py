"""The characteristic polynomial from the traces of powers (Newton's identities, proofs.determinants.charpoly)
is the determinant by entries, it reads no coordinate (so (chasles-cones-real) is proved on the equivariant
chart), and a corrupted matrix fails."""
from __future__ import annotations

from stiefelsym import admissible
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.proofs.determinants import charpoly, det


def _claim(func, cid="t-charpoly"):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7))


def _by_entries(s, M):
    shifted = s.scalar_matrix(s.lam, M.shape[0], "n") - M
    return det(s, [[shifted[i, j] for j in range(M.shape[0])] for i in range(M.shape[0])])


def test_charpoly_is_the_determinant_by_entries():
    def agree(s):
        M = s.generic("M", "n", "n")
        return {"charpoly - det": charpoly(s, M, s.lam) - _by_entries(s, M)}
    for n in (1, 2, 3, 4):
        res = run_exact(_claim(agree), n, 1, 0)
        assert res.verdict == "proved", (n, res.message)


def test_a_corrupted_charpoly_fails():
    def shifted(s):
        M = s.generic("M", "n", "n")
        return {"charpoly(M + I) - det(lam I - M)": charpoly(s, M + s.In, s.lam) - _by_entries(s, M)}
    assert run_exact(_claim(shifted), 3, 1, 0).verdict == "fails"


def test_the_cones_are_real_on_the_equivariant_chart():
    c = {x.id: x for x in load_catalog()}["chasles-cones-real"]
    res = run_exact(c, 4, 2, 0)
    assert res.verdict == "proved" and res.reductions[0].startswith("equivariance"), res.reductions

    def plus(s):          # the printed matrix with +PP^T: false
        Q = s.In - s.X @ s.X.T
        out = c.func(s)
        M = Q @ (s.A + s.P @ s.P.T) @ Q
        key = "lambda^r I_2r(lambda) - det(lambda I - Q(A - PP^T)Q)"
        out[key] = out[key] + charpoly(s, Q @ (s.A - s.P @ s.P.T) @ Q, s.lam) - charpoly(s, M, s.lam)
        return out
    bad = run_exact(_claim(plus, "t-cones-plus"), 4, 2, 0)
    assert bad.verdict == "fails" and bad.residual.startswith("lambda^r I_2r")
