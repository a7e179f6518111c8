"""dirac_bracket_for(standard_constraints) against the scene's own Dirac bracket s.bracket (cond_XP), with
functions that read no entry (for the dimension-free method too).  F = tr(XᵀKX), G = tr(PᵀLX) (K, L generic).
  s79r2-dirac-std-true:   dirac_bracket_for(standard_constraints)(F, G) = s.bracket(F, G)   TRUE (the same bracket)
  s79r2-dirac-std-false:  … = s.canonical_bracket(F, G)                                        FALSE (generically)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import dirac_bracket_for, standard_constraints

SZ = admissible(n_min=3, n_max=3)


def _FG(s):
    K, L = s.generic("K", "n", "n"), s.generic("L", "n", "n")
    return (lambda t: t.tr(t.X.T @ K @ t.X)), (lambda t: t.tr(t.P.T @ L @ t.X))


@claim("s79r2-dirac-std-true", kind="id", sizes=SZ)
def std_true(s):
    F, G = _FG(s)
    return {"D_std = {,}": dirac_bracket_for(standard_constraints)(s, F, G) - s.bracket(F, G)}


@claim("s79r2-dirac-std-false", kind="id", sizes=SZ)
def std_false(s):
    F, G = _FG(s)
    return {"D_std = {,}_0": dirac_bracket_for(standard_constraints)(s, F, G) - s.canonical_bracket(F, G)}
