"""Helper of claims2/twins2 (no claims)."""
from __future__ import annotations


def neumann_casimir(sign=-1):
    """f(x) = tr h² + sign·2 tr(A v) (x = h + v), ∇f = −4h − sign·4A (⟨∇f, δ⟩ = −½tr(∇f δ))."""
    from stiefelsym.brackets import MatrixFunction, skew, sym
    return MatrixFunction(lambda t, x: t.tr(skew(x) @ skew(x)) + sign * 2 * t.tr(t.A @ sym(x)),
                          lambda t, x: skew(x) * (-4) - t.A * (sign * 4), "tr h^2 - 2 tr Av")
