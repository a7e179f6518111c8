"""A nonzero residual of the exact method is tested and printed from the polynomial backend's own
scalars (rational functions in flint), not converted to symengine as a whole: the same nonzero entries
and the same canonical text as through symengine, and a corrupted claim is still refuted."""
from __future__ import annotations

from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.methods.fixed_size import _entries, _exact_text, _residual_entries
from stiefelsym.scene import Scene


def _residual(s):
    # a refuted statement: the Lax matrix of the Neumann flow differs from its transpose; its residual
    # has zero and nonzero entries, with denominators (the resolvent)
    R = s.resolvent(s.lam)
    L = s.X.T @ R @ s.P + s.P.T @ R @ s.X + s.lam * s.X.T @ s.A @ s.P
    return L - L.T


def test_the_backend_s_scalars_give_the_symengine_entries_and_text():
    f = SymbolicField()
    s = Scene(3, 2, f, chart="cayley")
    value = _residual(s)
    native = _residual_entries(value, "check")
    assert value._n is not None and type(native[0][1]).__name__ == "_RF"
    plain = _entries(_residual(Scene(3, 2, SymbolicField(), chart="cayley")), "check")
    assert [p for p, _ in native] == [p for p, _ in plain]
    bad = [(p, x) for p, x in native if not f.is_zero(x)]
    assert bad and len(bad) < len(native)        # some entries vanish (the diagonal), others do not
    for (_, x), (_, y) in zip(native, plain):
        assert f.is_zero(x) == SymbolicField().is_zero(y)
        if not f.is_zero(x):
            # the same canonical text, whole and cut short, as the entry through symengine
            assert _exact_text(f, x) == _exact_text(f, y)
            assert _exact_text(f, x, 40) == _exact_text(f, y, 40)


# -- the route used as a user would: false statements whose residual the exact method reads this way ------

from stiefelsym import admissible  # noqa: E402
from stiefelsym.claims import Claim  # noqa: E402
from stiefelsym.methods.fixed_size import run_exact, run_points  # noqa: E402


def _claim(func, cid, expect="holds"):
    return Claim(id=cid, paper=("test",), kind="id", section="t", func=func, sizes=admissible(4), expect=expect)


def resolvent_commutes_with_the_projector(s):
    """False for r < n: (λ − A)⁻¹ XXᵀ = XXᵀ (λ − A)⁻¹ (true at r = n, where XXᵀ = I)."""
    R, Q = s.resolvent(s.lam), s.X @ s.X.T
    return {"[R, XX^T]": R @ Q - Q @ R}


def one_entry_off(s):
    """False: a true identity (XᵀX = I) with one entry of a large product added off the diagonal."""
    R = s.resolvent(s.lam)
    M = s.X.T @ R @ s.A @ R @ s.X
    E = s.mat([[s.q(1) if (i, j) == (0, 1) else s.q(0) for j in range(s.r)] for i in range(s.r)], ("r", "r"))
    return {"X^T X - I + M_12 E_12": s.X.T @ s.X - s.Ir + E * M[0, 1]}


def test_false_statements_read_in_the_backend_s_scalars_fail_with_a_residual():
    for func, sizes in ((resolvent_commutes_with_the_projector, ((3, 1), (3, 2))), (one_entry_off, ((3, 2), (4, 2)))):
        c = _claim(func, "residual-entries-false")
        for n, r in sizes:
            res = run_exact(c, n, r, 0)
            assert res.verdict == "fails", (func.__name__, n, r, res.verdict, res.message)
            assert res.residual and " = " in res.residual
            assert run_points(c, n, r, "modular", 0).verdict == "fails"
    # at r = n the commutator vanishes (XXᵀ = I, on both components of O(n)): not refuted there
    assert run_exact(_claim(resolvent_commutes_with_the_projector, "residual-entries-rn"), 3, 3, 0).verdict == "proved"


def test_an_expected_nonvanishing_residual_is_decided_from_the_backend_s_scalars():
    """expect="nonzero": the commutator is proved not to vanish (its certificate prints an entry), and a
    statement that does vanish fails."""
    yes = run_exact(_claim(resolvent_commutes_with_the_projector, "residual-entries-nonzero", "nonzero"), 3, 2, 0)
    assert yes.verdict == "proved" and "not identically zero" in yes.certificate and " = " in yes.certificate
    no = run_exact(_claim(resolvent_commutes_with_the_projector, "residual-entries-zero", "nonzero"), 3, 3, 0)
    assert no.verdict == "fails"
