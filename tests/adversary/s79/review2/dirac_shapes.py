"""dirac_bracket_for's list, edge shapes (n = 3, r = 1 and 2).  F = (XᵀX)₁₁ + P₂₁, G = X₂₁.

  s79r2-dirac-empty-true:   constraints [] : the Dirac bracket of no constraint is the canonical one:
                            D(F, G) − {F, G}₀ = 0                                                         TRUE
  s79r2-dirac-0x0-true:     constraints [0×0 matrix] (no entry, no condition): the same                   TRUE
  s79r2-dirac-0x0-false:    [0×0] and D(F, G) = 0 ({F, G}₀ = −∂F/∂P₂₁·∂G/∂X₂₁ = −1 ≠ 0)             FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import dirac_bracket_for

SZ = admissible(n_min=3, n_max=3)


def _FG(s):
    F = lambda t: (t.X.T @ t.X)[0, 0] * 0 + t.P[1, 0] + (t.X.T @ t.X)[0, 0]  # noqa: E731
    G = lambda t: t.X[1, 0]  # noqa: E731
    return F, G


@claim("s79r2-dirac-empty-true", kind="id", sizes=SZ)
def empty_true(s):
    F, G = _FG(s)
    D = dirac_bracket_for(lambda t: [])
    return {"D(F, G) = {F, G}0": D(s, F, G) - s.canonical_bracket(F, G)}


@claim("s79r2-dirac-0x0-true", kind="id", sizes=SZ)
def zero_true(s):
    F, G = _FG(s)
    D = dirac_bracket_for(lambda t: [t.X[0:0, 0:0]])
    return {"D(F, G) = {F, G}0": D(s, F, G) - s.canonical_bracket(F, G)}


@claim("s79r2-dirac-0x0-false", kind="id", sizes=SZ)
def zero_false(s):
    F, G = _FG(s)
    D = dirac_bracket_for(lambda t: [t.X[0:0, 0:0]])
    return {"D(F, G) = 0": D(s, F, G)}


