"""Stop 56's review of the numeric methods: engine steps that a float or ball evaluation computed otherwise than
the exact fields do, so that a certified enclosure bounded a different value.

1. A point a claim gives (twisted.at_point) off V: the closed-form multipliers Π = sym(XᵀH_P), ... hold where
   XᵀX = I_r only.  The exact fields test that exactly and solve the multiplier system off V; floats and balls
   took the closed forms on trust ("the chart's point is on V by construction"), which is not the claim's point.
2. polynomial_gradient's degree in y, decided by a ball's "0 lies in the enclosure": a cubic term hidden under
   the radius of K tr(yᵀy), K = 2⁵², was taken for absent, and the interpolation at degree 2 gave a wrong
   gradient with an exact enclosure.
Each true statement below must never fail; each false one (expect="nonzero", or a wrong closed form) must never
pass, under every method."""
from stiefelsym import admissible, claim, twisted
from stiefelsym.brackets import polynomial_gradient

S = admissible(n_min=2, n_max=4)
K = 2 ** 52


def H(t):
    return t.tr(t.P.T @ t.A @ t.X)


def off_V(s):
    return twisted.at_point(s, s.X * 2, s.P)


# TRUE: the Dirac flow solved at (2X, P) is tangent to the level of XᵀX (its constraints are those of the level)
@claim("adv-s56-offv-tangent", kind="id", sizes=S)
def offv(s):
    s2 = off_V(s)
    return {"d tr XtX": s2.d(lambda t: t.tr(t.X.T @ t.X), s2.dirac_flow(H))}


# TRUE: the Dirac bracket of tr(XᵀX) with H at (2X, P)
@claim("adv-s56-offv-bracket", kind="id", sizes=S)
def offv_bracket(s):
    return {"br": off_V(s).bracket(lambda t: t.tr(t.X.T @ t.X), H)}


# TRUE: the same along the multiplier flow
@claim("adv-s56-offv-mult", kind="id", sizes=S)
def offv_mult(s):
    s2 = off_V(s)
    return {"d tr XtX": s2.d(lambda t: t.tr(t.X.T @ t.X), s2.multiplier_flow(H))}


# TRUE, another way off V: the point (X + P, P) (XᵀX = I_r fails there unless P = 0); the Dirac flow conserves
# every constraint function, here tr(XᵀP + PᵀX)
@claim("adv-s56-offv-shifted", kind="id", sizes=S)
def offv_shifted(s):
    s2 = twisted.at_point(s, s.X + s.P, s.P)
    return {"d tr(XtP + PtX)": s2.d(lambda t: t.tr(t.X.T @ t.P + t.P.T @ t.X), s2.dirac_flow(H))}


# FALSE: the first one said not to vanish
@claim("adv-s56-offv-tangent-nonzero", kind="id", sizes=S, expect="nonzero")
def offv_nonzero(s):
    s2 = off_V(s)
    return {"d tr XtX": s2.d(lambda t: t.tr(t.X.T @ t.X), s2.dirac_flow(H))}


# FALSE: the closed form's Ẋ at (2X, P) is not the solved flow's
@claim("adv-s56-offv-closed", kind="id", sizes=S)
def offv_closed(s):
    X2 = s.X * 2
    s2 = twisted.at_point(s, X2, s.P)
    HP = s.A @ X2
    Pi = (X2.T @ HP + HP.T @ X2) * s.q(1, 2)
    return {"Xdot": s2.dirac_flow(H)["X"] - (HP - X2 @ Pi)}


# TRUE control on V: at the chart's own point given again, the closed form is the flow
@claim("adv-s56-onv-closed", kind="id", sizes=S)
def onv_closed(s):
    s2 = twisted.at_point(s, s.X, s.P)
    HP = s.A @ s.X
    Pi = (s.X.T @ HP + HP.T @ s.X) * s.q(1, 2)
    return {"Xdot": s2.dirac_flow(H)["X"] - (HP - s.X @ Pi)}


def e11(t):
    return t.mat([[1] + [0] * (t.r - 1)] + [[0] * t.r for _ in range(t.r - 1)], ("r", "r"))


def hidden_cubic(t, y):
    a = t.tr(e11(t) @ y)
    return t.tr(y.T @ y) * K + a * a * a


def hidden_quartic(t, y):
    a = t.tr(e11(t) @ y)
    return t.tr(y.T @ y) * K + a * a * a * a * t.tr(t.X.T @ t.X)


# TRUE: the gradient at 0 of K tr(yᵀy) + y₁₁³ is 0
@claim("adv-s56-polygrad-zero", kind="id", sizes=S)
def grad_zero(s):
    return {"G": polynomial_gradient(s, hidden_cubic, s.zeros(s.r, s.r, ("r", "r")), "gl", "r")}


def big_square(t, y):
    return t.tr(y.T @ y) * K


def quartic(t, y):
    a = t.tr(e11(t) @ y)
    return a * a * a * a * t.tr(t.X.T @ t.X)


# TRUE: the gradient is additive, G(f + g) = G(f) + G(g), at y = I for f = K tr(yᵀy) and g = tr(XᵀX) y₁₁⁴ (a
# degree of f + g taken as 2 within an error bound would break it)
@claim("adv-s56-polygrad-additive", kind="id", sizes=S)
def grad_additive(s):
    def at(f):
        return polynomial_gradient(s, f, s.Ir, "gl", "r")
    return {"G": at(hidden_quartic) - at(big_square) - at(quartic)}


# FALSE: the first one said not to vanish
@claim("adv-s56-polygrad-nonzero", kind="id", sizes=S, expect="nonzero")
def grad_nonzero(s):
    return {"G": polynomial_gradient(s, hidden_cubic, s.zeros(s.r, s.r, ("r", "r")), "gl", "r")}


def seventh(t, y):
    a = t.tr(e11(t) @ y)
    return t.tr(y.T @ y) * K + a * a * a * a * a * a * a


# Beyond the highest degree, hidden under K tr(yᵀy): refused by the exact fields; floats and balls must not
# interpolate it at degree 6 and say "does not vanish" (the gradient at 0 is 0)
@claim("adv-s56-polygrad-seventh-nonzero", kind="id", sizes=S, expect="nonzero")
def grad_seventh(s):
    return {"G": polynomial_gradient(s, seventh, s.zeros(s.r, s.r, ("r", "r")), "gl", "r")}
