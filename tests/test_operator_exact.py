"""The generic symmetric operator on so(n) (``Scene.sym_operator``): its whole-matrix application
agrees with the defining sums over the coefficient matrix in every field and in the lifted scenes
(reverse and forward derivatives), and a corrupted operator claim is rejected by every method."""
from fractions import Fraction

import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.run.runner import run_one
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


# -- the encoded form of parameters beyond the flint ring's (polyfield._BigPoly) --------------

def _small_ring(monkeypatch, cap):
    """A fresh exact field whose flint ring holds only ``cap`` parameters: the rest are encoded."""
    from stiefelsym.backends import polyfield
    monkeypatch.setattr(polyfield, "MAX_VARS", cap)
    return SymbolicField()


def _mat(f, rows):
    import numpy as np
    from stiefelsym.backends.matrix import Mat
    a = np.empty((len(rows), len(rows[0])), dtype=object)
    for i, row in enumerate(rows):
        for j, x in enumerate(row):
            a[i, j] = x
    return Mat._wrap(a, f)


def test_encoded_products_of_two_parameters_are_not_identified(monkeypatch):
    """c1 c2 - c0 c3 vanishes under the encoding (u0v1·u1v0 = u0v0·u1v1): a product of two encoded
    values must leave the encoded form, and the difference is found nonzero."""
    f = _small_ring(monkeypatch, 1)
    w = f.param("w")
    c = [f.param(f"c{k}") for k in range(4)]
    W = _mat(f, [[w]])
    C = [_mat(f, [[x]]) @ W for x in c]        # encoded entries (w is the ring's one variable)
    D = C[1] @ C[2] - C[0] @ C[3]
    assert not D.is_zero()
    assert not f.is_zero(D._view()[0, 0])
    assert f.is_zero(f.normalize(D._view()[0, 0] - (c[1] * c[2] - c[0] * c[3]) * w * w))
    assert (C[1] @ C[2] - C[2] @ C[1]).is_zero()
    assert len(f.poly_ring().big_syms) == 4


@pytest.mark.parametrize("seed", range(6))
def test_encoded_arithmetic_agrees_with_symengine(monkeypatch, seed):
    """Random sums, products, transposes, scalings, traces and pairings of matrices whose entries
    involve parameters beyond the ring: every result equals symengine's expansion, and a result
    is zero exactly when symengine's is."""
    import random

    import numpy as np
    import symengine as se
    f = _small_ring(monkeypatch, 3)
    rng = random.Random(seed)
    ps = [f.param(f"p{k}") for k in range(9)]

    def entry():
        return se.Add(*[rng.randint(-2, 2) * rng.choice(ps) * (rng.choice(ps) if rng.random() < 0.3 else 1)
                        for _ in range(rng.randint(0, 3))] + [se.Integer(rng.randint(-1, 1))])

    def pair():
        a = np.array([[entry() for _ in range(3)] for _ in range(3)], dtype=object)
        return _mat(f, a.tolist()), a

    def same(M, a):
        v = M._view()
        for x, y in zip(v.flat, a.flat):
            d = se.expand(x - y)
            assert d == 0, (x, y)
        assert M.is_zero() == all(se.expand(y) == 0 for y in a.flat)

    for _ in range(4):
        (A, a), (B, b) = pair(), pair()
        same(A + B, a + b)
        same(A - B, a - b)
        same(A @ B.T, np.dot(a, b.T))
        same((A @ B) @ A, np.dot(np.dot(a, b), a))
        same(A - A, a - a)
        s = rng.choice(ps)
        same(A * s, a * s)
        assert se.expand(A.trace() - sum(a[i, i] for i in range(3))) == 0
        assert se.expand(A._inner(B) - sum(x * y for x, y in zip(a.flat, b.flat))) == 0
    assert f.poly_ring().big_syms              # the encoded form was exercised


@pytest.mark.parametrize("func,verdict", [(_flow_as_printed, "proved"), (_flow_corrupted, "fails")])
def test_operator_flow_with_encoded_coefficients(func, verdict, monkeypatch):
    """At (6, 3) the operator's 120 coefficients and the chart's 12 parameters exceed a flint ring of
    128 variables: the coefficients are encoded, and the exact verdicts are those of the small sizes."""
    from stiefelsym.backends import polyfield
    from stiefelsym.methods.fixed_size import run_exact
    monkeypatch.setattr(polyfield, "MAX_VARS", 128)
    res = run_exact(_claim(func), 6, 3, 0)
    assert res.verdict == verdict, res.message
    f = SymbolicField()
    residuals = func(Scene(6, 3, f, chart="equivariant"))
    assert f.poly_ring().big_syms                # the encoded form was used
    assert all(M.is_zero() for M in residuals.values()) == (verdict == "proved")
