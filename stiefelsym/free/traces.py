"""Trace forms: gradients by cyclic differentiation.

For a trace form H (a scalar :class:`~stiefelsym.free.algebra.NCPoly`: a
combination of products of traces of cyclic words), the gradient with respect
to a letter L is the matrix ∂H/∂L with dH = tr((∂H/∂L)ᵀ dL):

* an occurrence of L in tr(U L) (rotate L to the end) gives
  d tr(U L) = tr(U dL), so it contributes Uᵀ = U*;
* an occurrence of L* = s·Lᵀ in tr(V L*) gives d tr(V s dLᵀ) = s tr(dL Vᵀ),
  so it contributes s·V.

A product of traces is differentiated by the product rule.  The gradient is
that of the polynomial *as written* (the ambient function on R^{n×r}); the
constraints change it only by normal directions, which the multipliers of a
Dirac flow absorb.
"""
from __future__ import annotations

import symengine as se

from stiefelsym.free.algebra import SCALAR, Letter, NCPoly, OperatorLetter, apply_operator, refuse_moving


def gradient(H: NCPoly, L: Letter) -> NCPoly:
    """∂H/∂L for a trace form H and a letter L that is not self-adjoint (an L.row × L.col polynomial).

    An occurrence of L in the argument u of an operator letter 𝔸⟨u⟩ in tr(𝔸⟨u⟩V) is differentiated
    through the symmetry of 𝔸: d tr(𝔸(skew u)V) = tr(𝔸(skew du) skew V) = tr(du 𝔸(skew V)), so it
    contributes as the same occurrence in tr(u·𝔸⟨V⟩)."""
    if not H.is_scalar:
        raise TypeError("gradients are taken of scalar trace forms")
    if L.adjoint == L:
        raise TypeError(f"{L} is self-adjoint: its gradient is not defined for a general variation")
    refuse_moving(H, "a gradient")
    out = NCPoly.zero(L.row, L.col)
    for (tm, w), c in H.terms.items():
        for i, cyc in enumerate(tm):
            rest = NCPoly({(tm[:i] + tm[i + 1:], ()): c}, SCALAR, SCALAR)
            out = out + rest * _cycle_gradient(cyc, L)
    return out


def _cycle_gradient(cyc: tuple, L: Letter) -> NCPoly:
    """∂ tr(cyc)/∂L."""
    out = NCPoly.zero(L.row, L.col)
    for j, letter in enumerate(cyc):
        if isinstance(letter, OperatorLetter):
            if _mentions(letter, L):
                V = cyc[j + 1:] + cyc[:j]   # tr(𝔸⟨u⟩ V) = tr(u 𝔸(V))
                image = apply_operator(letter.operator, NCPoly.word(V, letter.row))
                for (_, vw), vc in image.terms.items():
                    out = out + _occurrences_gradient(letter.argument + vw, len(letter.argument), L) * vc
            continue
        if letter != L and letter != L.adjoint:
            continue
        out = out + _one_occurrence(cyc, j, L)
    return out


def _occurrences_gradient(cyc: tuple, upto: int, L: Letter) -> NCPoly:
    """∂ tr(cyc)/∂L from the occurrences of L at the positions before ``upto``."""
    out = NCPoly.zero(L.row, L.col)
    for j in range(upto):
        letter = cyc[j]
        if isinstance(letter, OperatorLetter):
            if _mentions(letter, L):
                raise TypeError(f"the gradient of an operator nested in an operator's argument ({letter})")
            continue
        if letter == L or letter == L.adjoint:
            out = out + _one_occurrence(cyc, j, L)
    return out


def _one_occurrence(cyc: tuple, j: int, L: Letter) -> NCPoly:
    letter = cyc[j]
    U = cyc[j + 1:] + cyc[:j]  # tr(U · letter)
    mono = NCPoly.word(U, letter.col)   # letter.col: the type the empty U would have
    if letter == L:
        return mono.star()
    return mono * se.Integer(L.adjoint_sign)


def _mentions(op: OperatorLetter, L: Letter) -> bool:
    """L or its adjoint occurs in the argument of the operator letter op (at any depth)."""
    return any(x == L or x == L.adjoint or (isinstance(x, OperatorLetter) and _mentions(x, L))
               for x in op.argument)
