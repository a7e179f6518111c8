"""The generic symmetric operator on so(n) (``Scene.sym_operator``): its whole-matrix application
agrees with the defining sums over the coefficient matrix in every field and in the lifted scenes
(reverse and forward derivatives), and a corrupted operator claim is rejected by every method."""
from fractions import Fraction

import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.fields import SymbolicField
from stiefelsym.runner import run_one
from stiefelsym.scene import Scene


def _reference(scene, name, xi):
    """AA(xi) entry by entry: sum_l c_kl <xi, E_l> on the basis E_i ∧ E_j (the definition)."""
    basis, coeffs = scene._operator_coefficients(name)
    f = scene._field
    a, c = xi._view(), coeffs._view()
    half = f.const(Fraction(1, 2))
    comps = [(a[i, j] - a[j, i]) * half for (i, j) in basis]
    out = {}
    for k, (i, j) in enumerate(basis):
        acc = f.const(0)
        for l, x in enumerate(comps):
            acc = acc + x * c[k, l]
        out[i, j] = f.normalize(acc)
    return out


@pytest.mark.parametrize("n,r", [(3, 2), (4, 2), (4, 4)])
def test_apply_is_the_defining_sum(n, r):
    f = SymbolicField()
    s = Scene(n, r, f, chart="equivariant")
    xi = s.Phi + s.X @ s.X.T        # a symmetric part too: the operator sees the skew part only
    out = s.sym_operator("AA")(xi)._view()
    ref = _reference(s, "AA", xi)
    for i in range(n):
        assert f.is_zero(out[i, i])
        for j in range(i + 1, n):
            assert f.is_zero(f.normalize(out[i, j] - ref[i, j]))
            assert f.is_zero(f.normalize(out[j, i] + ref[i, j]))


def _H(t):
    return t.killing(t.sym_operator("AA")(t.Phi), t.Phi) / 2


@pytest.mark.parametrize("n,r", [(3, 1), (4, 3)])
def test_reverse_gradient_through_the_operator(n, r):
    """Reverse mode (one product per application in the tape) agrees with the 2nr forward passes."""
    f = SymbolicField()
    s = Scene(n, r, f, chart="equivariant")
    HX, HP = s._reverse_gradient(_H)
    row = s._jacobian(_H, scalar=True)[0]
    got = list(HX._view().flat) + list(HP._view().flat)
    assert len(got) == len(row)
    for x, y in zip(got, row):
        assert f.is_zero(f.normalize(x - y))


def _flow_as_printed(s):
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(_H)
    return {"dX/dt": flow.Xdot - AA(s.Phi) @ s.X, "dP/dt": flow.Pdot - AA(s.Phi) @ s.P}


def _flow_corrupted(s):
    """The operator applied to -Phi (a sign error): must fail everywhere."""
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(_H)
    return {"dX/dt": flow.Xdot - AA(s.Phi.T) @ s.X, "dP/dt": flow.Pdot - AA(s.Phi) @ s.P}


def _claim(func):
    return Claim(id="test-operator", paper=("prep",), kind="id", section="t", func=func, sizes=admissible(4))


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float"])
def test_operator_flow_negative_control(method):
    good = run_one(_claim(_flow_as_printed), Size(3, 2), method, 0)
    bad = run_one(_claim(_flow_corrupted), Size(3, 2), method, 0)
    assert good.verdict in ("proved", "checked", "numeric"), good.message
    assert bad.verdict == "fails", bad.message
