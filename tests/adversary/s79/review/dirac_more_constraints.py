"""dirac_bracket_for(constraints) reads only constraints(t)[0] and [1] (brackets.py:87-94, `for k in range(2)`):
a list of four constraint matrices is silently taken as its first two.  The module's doc says "the Dirac bracket of
any list of symmetric matrix constraints".  r = 1, n = 3 (every 1x1 matrix is symmetric):

  c1 = XᵀX − 1, c2 = XᵀP + PᵀX, c3 = X11, c4 = P11  (second class where 4|X|² − 4X11² ≠ 0: the Pfaffian of
  ({c_i, c_j}_0) is {c1,c2}{c3,c4} − {c1,c3}{c2,c4} + {c1,c4}{c2,c3} = 4|X|²·1 − 0 + 2X11·(−2X11)).
  For a constraint c3 = F_3 of the list, {c3, f}_D = {F_3, f} − Σ_ij {F_3, F_i} C_ij {F_j, f} = {F_3,f} − {F_3,f} = 0
  for every f (Σ_i {F_3, F_i} C_ij = δ_3j).

  s79-dirac4-casimir-true:   {X11, tr(XᵀAX)/2 + P21}_D(c1..c4) = 0                                 (TRUE)
  s79-dirac4-equals2-false:  {X11, f}_D(c1..c4) = {X11, f}_D(c1, c2)   (the sphere's Dirac bracket; FALSE:
                             the right side is the derivative of f along the sphere's X11-flow, not 0)
  s79-dirac2-control:        {X11, f}_D(c1, c2) = 0 (FALSE; control that the sphere bracket is not 0)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import dirac_bracket_for

SZ = admissible(n_min=3, n_max=3, r_min=1, r_max=1)


def four(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X, t.X[0:1, 0:1], t.P[0:1, 0:1]]


def two(t):
    return four(t)[:2]


def x11(t):
    return t.X[0, 0]


def f(t):
    return t.tr(t.X.T @ t.A @ t.X) / 2 + t.P[1, 0]


@claim("s79-dirac4-casimir-true", kind="id", sizes=SZ)
def d4_true(s):
    return {"{X11, f}_D4": dirac_bracket_for(four)(s, x11, f)}


@claim("s79-dirac4-equals2-false", kind="id", sizes=SZ)
def d4_false(s):
    return {"{X11, f}_D4 − {X11, f}_D2": dirac_bracket_for(four)(s, x11, f) - dirac_bracket_for(two)(s, x11, f)}


@claim("s79-dirac2-control", kind="id", sizes=SZ)
def d2_control(s):
    return {"{X11, f}_D2": dirac_bracket_for(two)(s, x11, f)}
