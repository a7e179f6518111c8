"""The linear algebra of the stacked gradients (stiefelsym.systems) keeps a symbolic solution in the flint
backend: the solve M⁻¹B and the cut of a column of coordinates into the variables' matrices give the same
values as the field's own solver and the cut of the entries, and a singular system is refused alike."""
from __future__ import annotations

import random

import numpy as np
import pytest

from stiefelsym.backends.fields import DegenerateError, ModularField
from stiefelsym.backends.matrix import Mat
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.scene import Scene
from stiefelsym.systems import _Algebra, _Layout, real_coordinates


def _scene(field=None) -> Scene:
    return Scene(3, 2, field or SymbolicField(), chart="equivariant", rng=random.Random(5))


def _params(s: Scene, name: str, m: int, k: int) -> np.ndarray:
    a = np.empty((m, k), dtype=object)
    for i in range(m):
        for j in range(k):
            a[i, j] = s.field.param(f"{name}{i}{j}", s._rng)
    return a


def _same(f, x, y) -> bool:
    return all(f.is_zero(f.normalize(a - b)) for a, b in zip(np.asarray(x).flat, np.asarray(y).flat))


def test_the_symbolic_solve_stays_in_the_backend_and_agrees_with_the_fields_solver():
    s = _scene()
    alg = _Algebra(s)
    M = _params(s, "m", 3, 3)
    B = _params(s, "b", 3, 2)
    got = alg.solve(alg.of(M), alg.of(B), "the test system")
    assert got._n is not None and got._obj is None         # held by the backend, not converted
    want = s.field.solve(M.tolist(), B.tolist())
    assert _same(s.field, got._view(), want)
    residual = alg.mm(alg.of(M), got)._view() - B
    assert all(s.field.is_zero(s.field.normalize(x)) for x in residual.flat)


@pytest.mark.parametrize("make", [SymbolicField, lambda: ModularField(2**61 - 1)])
def test_a_singular_system_is_refused_with_the_same_message(make):
    s = _scene(make())
    alg = _Algebra(s)
    one, two = s.const(1), s.const(2)
    M = np.array([[one, two], [two, s.const(4)]], dtype=object)
    B = np.array([[one], [one]], dtype=object)
    with pytest.raises(DegenerateError, match="the test system is singular here"):
        alg.solve(alg.of(M), alg.of(B), "the test system")


def test_the_cut_of_a_column_in_the_backend_gives_the_matrices_of_the_entries():
    s = _scene()
    point = {"X": s.X, "P": s.P}
    layout = _Layout(s, real_coordinates(s, list(point)), point)
    c = _params(s, "c", layout.size, 1)
    native = layout.assemble(_Algebra(s).of(c), point)
    entries = layout.assemble(c, point)
    assert set(native) == set(entries) == {"X", "P"}
    for name in native:
        assert native[name]._n is not None                  # cut in the backend
        assert native[name].tags == entries[name].tags
        assert _same(s.field, native[name]._view(), entries[name]._view())


def test_negative_control_a_changed_column_gives_other_matrices():
    """The comparison above can fail: one changed coordinate changes the cut."""
    s = _scene()
    point = {"X": s.X, "P": s.P}
    layout = _Layout(s, real_coordinates(s, list(point)), point)
    c = _params(s, "c", layout.size, 1)
    d = c.copy()
    d[-1, 0] = d[-1, 0] + s.const(1)
    a = layout.assemble(_Algebra(s).of(c), point)
    b = layout.assemble(_Algebra(s).of(d), point)
    assert not _same(s.field, a["P"]._view(), b["P"]._view())
    assert isinstance(a["X"], Mat)
