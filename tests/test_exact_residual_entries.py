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
