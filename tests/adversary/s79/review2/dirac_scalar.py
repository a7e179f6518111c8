"""dirac_bracket_for with a scalar (not a 1×1 matrix) in its list (n = 3, r = 1): X₁₁ as t.X[0, 0].
Truth (review W3's): for the second-class set (c1, c2, X₁₁, P₁₁), {X₁₁, f}_D = 0.
  s79r2-dirac-scalar-true:   D(X11, f) = 0 with the list [c1, c2, X[0,0], P[0,0]]   TRUE (or a clear refusal)
  s79r2-dirac-scalar-false:  D(X11, f) = {X11, f}_{D2}                                FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import dirac_bracket_for

SZ = admissible(n_min=3, n_max=3, r_min=1, r_max=1)


def four(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X, t.X[0, 0], t.P[0, 0]]


def two(t):
    return four(t)[:2]


def x11(t):
    return t.X[0, 0]


def f(t):
    return t.tr(t.X.T @ t.A @ t.X) / 2 + t.P[1, 0]


@claim("s79r2-dirac-scalar-true", kind="id", sizes=SZ)
def t_(s):
    return {"D(X11, f) = 0": dirac_bracket_for(four)(s, x11, f)}


@claim("s79r2-dirac-scalar-false", kind="id", sizes=SZ)
def f_(s):
    return {"D(X11, f) = D2": dirac_bracket_for(four)(s, x11, f) - dirac_bracket_for(two)(s, x11, f)}
