# ruff: noqa
"""Probes: the ambient gradient s.gradient(H) depends on H off T*V.  Two Hamiltonians that agree on T*V have
different gradients; these claims are FALSE (declared fails_at everywhere they are false, numpy-checked in
indep.py's gradient section)."""
from stiefelsym import admissible, claim

E = "false: the gradients of two functions that agree on T*V differ"


@claim("g71b-gradient-constraint-added", paper=("dot_XP",), kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: True, erratum=E)
def gradient_constraint_added(s):
    """∂/∂X of ½tr PᵀP + tr(XᵀX − I) equals ∂/∂X of ½tr PᵀP (false: they differ by 2X)."""
    H1 = lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.X - t.Ir)
    H0 = lambda t: t.tr(t.P.T @ t.P) / 2
    return {"∂H1/∂X − ∂H0/∂X": s.gradient(H1)[0] - s.gradient(H0)[0]}


@claim("g71b-gradient-normal-two-forms", paper=("normal_metric", "dot_XP"), kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: n >= 2, erratum=E)
def gradient_normal_two_forms(s):
    """∂/∂X of ½⟨Φ, Φ⟩ equals ∂/∂X of ½tr PᵀP − ½tr (XᵀP)² (equal on T*V as functions, not as gradients: they
    differ by XPᵀP; false for n ≥ 2 — at (1,1) P = 0)."""
    H2 = lambda t: -t.tr((t.P @ t.X.T - t.X @ t.P.T) @ (t.P @ t.X.T - t.X @ t.P.T)) / 4
    H1 = lambda t: t.tr(t.P.T @ t.P) / 2 - t.tr(t.X.T @ t.P @ t.X.T @ t.P) / 2
    return {"∂H2/∂X − ∂H1/∂X": s.gradient(H2)[0] - s.gradient(H1)[0]}


@claim("g71b-gradient-constraint-true", paper=("dot_XP",), kind="id", sizes=admissible(n_max=4))
def gradient_constraint_true(s):
    """control (true): ∂/∂X of ½tr PᵀP + tr(XᵀX − I) is 2X."""
    H1 = lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.X - t.Ir)
    return {"∂H1/∂X − 2X": s.gradient(H1)[0] - 2 * s.X}
