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

from .algebra import SCALAR, Letter, NCPoly


def gradient(H: NCPoly, L: Letter) -> NCPoly:
    """∂H/∂L for a trace form H and a letter L that is not self-adjoint (an L.row × L.col polynomial)."""
    if not H.is_scalar:
        raise TypeError("gradients are taken of scalar trace forms")
    if L.adjoint == L:
        raise TypeError(f"{L} is self-adjoint: its gradient is not defined for a general variation")
    out = NCPoly.zero(L.row, L.col)
    for (tm, w), c in H.terms.items():
        for i, cyc in enumerate(tm):
            rest = NCPoly({(tm[:i] + tm[i + 1:], ()): c}, SCALAR, SCALAR)
            for j, letter in enumerate(cyc):
                if letter != L and letter != L.adjoint:
                    continue
                U = cyc[j + 1:] + cyc[:j]  # tr(U · letter)
                t = letter.col  # type the empty U would have
                mono = NCPoly.word(U, t)
                if letter == L:
                    out = out + rest * mono.star()
                else:
                    out = out + rest * mono * se.Integer(L.adjoint_sign)
    return out
