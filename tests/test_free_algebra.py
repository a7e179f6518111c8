"""The free algebra with involution: typing, *, traces, gradients, evaluation."""
from __future__ import annotations

import random
from fractions import Fraction

import numpy as np
import pytest
import symengine as se

from stiefelsym.free.algebra import DIMENSIONS, NCPoly, cycle_rep, evaluate, letter_pair, skew_letter, substitute, trace
from stiefelsym.free.scene import LAMBDA, A, P, Pt, X, Xt
from stiefelsym.free.traces import gradient
from free_words import random_word

XI = skew_letter("xi_test", "n", r"\xi")
LETTERS = [X, Xt, P, Pt, A, XI, LAMBDA]
kappa, lam = se.Symbol("kappa"), se.Symbol("lambda")


def w(*letters):
    return NCPoly.word(letters)


def random_poly(rng: random.Random, row: str, col: str, terms: int = 4) -> NCPoly:
    p = NCPoly.zero(row, col)
    for _ in range(terms):
        c = rng.choice([1, -2, 3]) * rng.choice([se.Integer(1), kappa, lam, kappa * lam + 1])
        p = p + NCPoly.word(random_word(rng, LETTERS, row, col, rng.randint(0, 4)), row, c)
    return p


TYPES = [("n", "r"), ("r", "n"), ("n", "n"), ("r", "r")]


@pytest.mark.parametrize("seed", range(5))
def test_involution_is_an_anti_automorphism(seed):
    rng = random.Random(seed)
    for a, b in TYPES:
        for c in ("n", "r"):
            p, q = random_poly(rng, a, b), random_poly(rng, b, c)
            assert (p * q).star() == q.star() * p.star()
            assert p.star().star() == p
            p2 = random_poly(rng, a, b)
            assert (p + p2).star() == p.star() + p2.star()
            assert (p * kappa).star() == p.star() * kappa


def test_letters_have_types_and_partners():
    assert (X.row, X.col) == ("n", "r") and X.adjoint is Xt and Xt.adjoint is X
    assert A.adjoint is A and LAMBDA.adjoint is LAMBDA
    assert w(XI).star() == -w(XI)
    assert w(Xt, P).star() == w(Pt, X)


def test_ill_typed_products_and_sums_raise():
    with pytest.raises(TypeError):
        w(X) * w(X)
    with pytest.raises(TypeError):
        NCPoly.word((X, X))
    with pytest.raises(TypeError):
        w(X) + w(Xt)
    with pytest.raises(TypeError):
        NCPoly.identity("n") + NCPoly.identity("r")
    with pytest.raises(TypeError):
        w(X) + 1  # c·I must be explicit
    assert (NCPoly.identity("n") * w(X)) == w(X)
    assert (w(X) * NCPoly.identity("r")) == w(X)


def test_scalars_multiply_from_both_sides():
    p = w(X, Pt)
    assert p * 2 == 2 * p == p + p
    assert p * Fraction(1, 2) * 2 == p
    assert p * lam == lam * p
    assert (p / 2) * 2 == p
    t = trace(w(Pt, P))
    assert t * p == p * t  # traces are central
    assert (t * p).shape == ("n", "n")


def test_trace_is_cyclic_and_star_invariant():
    rng = random.Random(11)
    for _ in range(20):
        p, q = random_poly(rng, "n", "r"), random_poly(rng, "r", "n")
        assert trace(p * q) == trace(q * p)
        assert trace(p * q) == trace((p * q).star())
    assert trace(NCPoly.identity("r")) == NCPoly.scalar(DIMENSIONS["r"])
    assert trace(NCPoly.identity("n")) == NCPoly.scalar(DIMENSIONS["n"])
    assert trace(w(XI)) == 0  # skew
    assert cycle_rep((X, XI, Xt))[0] == 0
    with pytest.raises(TypeError):
        trace(w(X))


def test_substitution_is_a_homomorphism_with_adjoints():
    rng = random.Random(5)
    img = random_poly(rng, "n", "r")
    p, q = random_poly(rng, "r", "n"), random_poly(rng, "n", "n")
    s = {X: img}
    assert substitute(p * q, s) == substitute(p, s) * substitute(q, s)
    assert substitute(w(Xt), s) == img.star()
    assert substitute(trace(w(Xt, X)), s) == trace(img.star() * img)


def test_latex_uses_the_papers_notation():
    p = w(Xt, P) * 2 - w(Pt, P) * kappa + NCPoly.identity("r")
    s = p.latex()
    assert "X^{T} P" in s and r"\kappa P^{T} P" in s and r"\mathbf{I}_{r}" in s
    assert r"\operatorname{tr}" in trace(w(Pt, P)).latex()
    assert NCPoly.zero("n", "r").latex() == "0"


def neumann_hamiltonian_poly() -> NCPoly:
    half = se.Integer(1) / 2
    return (trace(w(Pt, P)) * half - trace(w(Xt, P, Xt, P)) * (half + kappa) + trace(w(Xt, A, X)) * half)


def test_gradient_of_the_neumann_hamiltonian_is_the_papers():
    """Proof of Prop. (No): ∂H/∂P = P − (1+2κ)XPᵀX, ∂H/∂X = AX − (1+2κ)PXᵀP (no constraints used)."""
    H = neumann_hamiltonian_poly()
    assert gradient(H, P) == w(P) - w(X, Pt, X) * (1 + 2 * kappa)
    assert gradient(H, X) == w(A, X) - w(P, Xt, P) * (1 + 2 * kappa)


def directional_derivative(H: NCPoly, variations: dict) -> NCPoly:
    """d/dt H(L + t·δL) at t = 0: replace one occurrence at a time (δ(L*) = (δL)*)."""
    total = NCPoly.zero("1", "1")
    for (tm, _), c in H.terms.items():
        for i, cyc in enumerate(tm):
            rest = NCPoly({(tm[:i] + tm[i + 1:], ()): c}, "1", "1")
            for j, K in enumerate(cyc):
                if K in variations:
                    rep = variations[K]
                elif K.adjoint in variations:
                    rep = variations[K.adjoint].star()
                else:
                    continue
                word = NCPoly.identity(cyc[0].row)
                for k, K2 in enumerate(cyc):
                    word = word * (rep if k == j else w(K2))
                total = total + rest * trace(word)
    return total


@pytest.mark.parametrize("seed", range(4))
def test_gradient_is_the_directional_derivative(seed):
    """d/dt H(X + tV, P + tW) = tr(H_Xᵀ V) + tr(H_Pᵀ W) in the free algebra (no constraints)."""
    rng = random.Random(seed)
    H = NCPoly.zero("1", "1")
    for _ in range(3):
        H = H + trace(random_poly(rng, "r", "r", 2)) * rng.choice([1, kappa])
    H = H * trace(random_poly(rng, "n", "n", 1)) + H
    V, _ = letter_pair("V", "Vt", "n", "r")
    W, _ = letter_pair("W", "Wt", "n", "r")
    lhs = directional_derivative(H, {X: w(V), P: w(W)})
    rhs = trace(gradient(H, X).star() * w(V)) + trace(gradient(H, P).star() * w(W))
    assert lhs == rhs


def test_evaluate_is_a_homomorphism():
    rng = random.Random(2)
    n, r = 4, 2
    vals = {str(L): np.array([[Fraction(rng.randint(-5, 5)) for _ in range(r if L.col == "r" else n)]
                              for _ in range(n if L.row == "n" else r)], dtype=object) for L in (X, P)}
    Am = np.array([[Fraction(rng.randint(-5, 5)) for _ in range(n)] for _ in range(n)], dtype=object)
    vals["A"] = Am + Am.T
    vals[str(LAMBDA)] = np.array([[1, 2], [2, 5]], dtype=object)
    vals[str(XI)] = np.array([[0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 0, 2], [0, 0, -2, 0]], dtype=object)
    sc = {kappa: Fraction(3, 7), lam: Fraction(-2)}
    for _ in range(10):
        p, q = random_poly(rng, "n", "r"), random_poly(rng, "r", "r")
        assert (evaluate(p * q, vals, sc) == evaluate(p, vals, sc).dot(evaluate(q, vals, sc))).all()
        assert (evaluate(p.star(), vals, sc) == evaluate(p, vals, sc).T).all()
        t = evaluate(trace(q), vals, sc)
        assert t == sum(np.diag(evaluate(q, vals, sc)), Fraction(0))


def test_memoized_transposes_and_cycle_representatives_need_the_same_letters():
    """Words compare by letter names: a memo hit must not hand one scene's letter to another."""
    rng = random.Random(7)
    for row, col in TYPES:
        p = random_poly(rng, row, col)
        assert p.star() is p.star() and p.star().star() is p
        fresh = NCPoly(p.terms, row, col)
        assert fresh.star() == p.star() and fresh.star().star() == p
    G, Gt = letter_pair("gen:G", "gen:G^T", "n", "r")
    H, Ht = letter_pair("gen:G", "gen:G^T", "n", "r")   # another scene's letters, of the same names

    def only(word, *allowed):
        return all(any(L is M for M in allowed) for L in word)

    for _ in range(2):
        assert only(cycle_rep((Gt, X))[1], G, Gt, X, Xt) and only(cycle_rep((Ht, X))[1], H, Ht, X, Xt)
        assert only(next(iter(NCPoly.word((X, Gt)).star().terms))[1], G, Gt, X, Xt)
        assert only(next(iter(NCPoly.word((X, Ht)).star().terms))[1], H, Ht, X, Xt)


def test_lazy_normalization_keeps_simplified_polynomials_and_collects_the_others():
    from stiefelsym.free.rewriting import is_simplified
    from stiefelsym.free.scene import FreeField, standard_system
    f = FreeField(standard_system(), lazy=True)
    p = w(X, Pt) * (1 + 2 * kappa) + w(P, Xt) * 3
    q = f.normalize(p)
    assert q.terms[((), (X, Pt))] == 1 + 2 * kappa and is_simplified(1 + 2 * kappa)
    assert f.normalize(q) is q
    hidden = (kappa + 1) ** 2 - kappa ** 2 - 2 * kappa - 1
    r = f.normalize(q + w(X, Pt) * hidden - w(P, Xt) * 3)
    assert set(r.terms) == {((), (X, Pt))} and not is_simplified(hidden) and not is_simplified(se.Integer(0))


def test_latex_of_rational_coefficients_is_sympys_without_sympy():
    import sympy
    from stiefelsym.free.algebra import _TERM_LATEX, _coef_parts
    rng = random.Random(3)
    values = [se.Integer(0), se.Integer(1), se.Integer(-1), se.Integer(10 ** 25), se.Rational(-10 ** 20, 3)]
    values += [se.Rational(rng.randint(-50, 50), rng.randint(1, 30)) for _ in range(100)]
    for c in values + [kappa, -2 * kappa * lam + 1, se.Rational(-1, 2) * lam]:
        _TERM_LATEX.pop(c, None)
        e = sympy.sympify(c._sympy_())
        neg = e.could_extract_minus_sign()
        mag = -e if neg else e
        assert _coef_parts(c) == ("- " if neg else "+ ", None if mag == 1 else sympy.latex(mag),
                                  isinstance(mag, sympy.Add))
