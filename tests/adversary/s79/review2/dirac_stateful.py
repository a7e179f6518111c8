"""dirac_bracket_for's constraints callable is read at several places (constraints(s) once per bracket for the
list's length and shapes, constraints(t) by every scalar constraint on the derived scenes) and is not held to
one function (no same_scene_function, unlike linear/scaled/trace_power/poisson_map_residual).  A callable whose
state (a mode the claim flips) makes it the four constraints of s79/review's W3 for one bracket and the sphere's
two for the next gives one object D two brackets.

n = 3, r = 1: c1 = XᵀX − 1, c2 = XᵀP + PᵀX, c3 = X11, c4 = P11; f = tr(XᵀAX)/2 + P21.
Truth (review W3's, its numpy dirac_more_constraints_check.py.in): {X11, f}_D4 = 0 ({c3, ·}_D = 0 for a constraint
of a second-class set), {X11, f}_D2 ≠ 0 (the sphere's Dirac bracket; the engine refutes "= 0", s79-dirac2-control).
  s79r2-dirac-state-contradiction:  D(X11, f) = 0  and  D(X11, f) = {X11, f}_{D2 of the sphere, another object}
     for ONE bracket D (of whatever constraints): both mean {X11, f}_{D2} = 0 — FALSE
  s79r2-dirac-state-control:        the same with two objects D4, D2 (no state): FALSE, must fail
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


@claim("s79r2-dirac-state-contradiction", kind="id", sizes=SZ)
def contra(s):
    mode = ["4"]
    D = dirac_bracket_for(lambda t: four(t) if mode[0] == "4" else two(t))
    first = D(s, x11, f)
    mode[0] = "2"
    second = D(s, x11, f)
    return {"D(X11, f) = 0": first, "D(X11, f) = {X11, f}_D2": second - dirac_bracket_for(two)(s, x11, f)}


@claim("s79r2-dirac-state-control", kind="id", sizes=SZ)
def control(s):
    D4, D2 = dirac_bracket_for(four), dirac_bracket_for(two)
    return {"D4(X11, f) = 0": D4(s, x11, f), "D4(X11, f) = D2(X11, f)": D4(s, x11, f) - D2(s, x11, f)}
