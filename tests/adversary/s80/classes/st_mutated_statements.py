"""Statements (Rank, Count) whose frozen fields are rewritten after __post_init__ (object.__setattr__).

Truth (by hand, at (3,2)):
* Ψ = XᵀP − PᵀX is a 2x2 skew matrix: generic rank 2, rank 0 at points with XᵀP symmetric (P = 0).
  So "rank Ψ = 2 at every point" is FALSE; "generic rank Ψ = 2" is TRUE.
* XᵀX = I_2 has rank 2 everywhere (TRUE at every point); rank 1 FALSE.
"""
from fractions import Fraction

from stiefelsym import Count, Rank, admissible, claim

SZ = admissible(n_max=3, n_min=3, r_min=2, r_max=2)


def _set(obj, **kw):
    for k, v in kw.items():
        object.__setattr__(obj, k, v)
    return obj


@claim("st-gen-str", kind="dim", sizes=SZ)
def st_gen_str(s):
    """FALSE: rank Ψ = 2 at every point, generic flag rewritten to a truthy string."""
    return {"rk": _set(Rank(s.Psi, 2, generic=False), generic="at every point")}


@claim("st-gen-zero", kind="dim", sizes=SZ)
def st_gen_zero(s):
    """TRUE statement read either way? generic=0: every-point rank 2 of Ψ is FALSE; generic TRUE."""
    return {"rk": _set(Rank(s.Psi, 2, generic=True), generic=0)}


@claim("st-gen-none", kind="dim", sizes=SZ)
def st_gen_none(s):
    """generic=None (falsy): at every point rank Ψ = 2 is FALSE."""
    return {"rk": _set(Rank(s.Psi, 2, generic=True), generic=None)}


@claim("st-exp-frac", kind="dim", sizes=SZ)
def st_exp_frac(s):
    """FALSE: rank XᵀX = 1 with expected rewritten to Fraction(1)."""
    return {"rk": _set(Rank(s.X.T @ s.X, 2), expected=Fraction(1))}


@claim("st-exp-true", kind="dim", sizes=SZ)
def st_exp_true(s):
    """FALSE: rank XᵀX = 1 (True) with expected rewritten to the bool True."""
    return {"rk": _set(Rank(s.X.T @ s.X, 2), expected=True)}


@claim("st-exp-float", kind="dim", sizes=SZ)
def st_exp_float(s):
    """FALSE: rank XᵀX = 1.5 (a float)."""
    return {"rk": _set(Rank(s.X.T @ s.X, 2), expected=1.5)}


@claim("st-count-tracer", kind="dim", sizes=SZ)
def st_count_tracer(s):
    """FALSE: Count whose value is the traced number tr(XXᵀ) (= 2) and expected 3."""
    return {"c": _set(Count(3, 3), value=s.tr(s.X @ s.X.T))}


@claim("st-count-bool", kind="dim", sizes=SZ)
def st_count_bool(s):
    """FALSE as a count: value True (a bool) against 1? (bool is not a count)"""
    return {"c": _set(Count(2, 1), value=True)}


@claim("st-count-frac", kind="dim", sizes=SZ)
def st_count_frac(s):
    """FALSE: Count 7/2 == 7/2? a count is an int; Fractions not counts."""
    return {"c": _set(Count(0, 1), value=Fraction(7, 2), expected=Fraction(7, 2))}


@claim("st-rank-ctrl", kind="dim", sizes=SZ)
def st_rank_ctrl(s):
    """TRUE control: generic rank Ψ = 2 and rank XᵀX = 2 at every point."""
    return {"a": Rank(s.Psi, 2), "b": Rank(s.X.T @ s.X, 2, generic=False)}


@claim("st-rank-false-ctrl", kind="dim", sizes=SZ)
def st_rank_false_ctrl(s):
    """FALSE control: rank Ψ = 2 at every point."""
    return {"a": Rank(s.Psi, 2, generic=False)}
