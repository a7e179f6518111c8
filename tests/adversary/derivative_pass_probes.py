"""Derivatives along flows and gradients written into the graph (stiefelsym/ir/derivative.py), and the
engine's polynomial_gradient step, probed with expressions the rules must each get right: entries, a
realified pair, the second point Y, a negative power, a quotient of numbers and a matrix divided by a
number inside a gradient, the pairing <a, b> = −½ tr(ab) of rectangular factors; and forms with no
degree (an inverse of the point) or one above the step's cap.  Each true claim passes under every
fixed-size method, each false one fails (or is refused), and the dimension-free method proves no false one.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import polynomial_gradient

ALL = admissible(n_max=4, n_min=2)
@claim("adv-dp-d-entries-true", kind="id", sizes=ALL)
def d_entries_true(s):
    V, W = s.A @ s.X, s.P
    F = lambda u: u.X[0, 0] * u.P[1, 0]
    return {"v": s.d(F, {"X": V, "P": W}) - (V[0, 0] * s.P[1, 0] + s.X[0, 0] * W[1, 0])}


@claim("adv-dp-d-entries-false", kind="id", sizes=ALL)
def d_entries_false(s):
    V, W = s.A @ s.X, s.P
    F = lambda u: u.X[0, 0] * u.P[1, 0]
    return {"v": s.d(F, {"X": V, "P": W}) - V[0, 0] * s.P[1, 0]}


@claim("adv-dp-d-realify-true", kind="id", sizes=ALL)
def d_realify_true(s):
    V, W = s.A @ s.X, s.A @ s.P
    F = lambda u: u.tr(u.realify(u.X, u.P).T @ u.realify(u.X, u.P))
    return {"v": s.d(F, {"X": V, "P": W}) - 4 * s.tr(s.X.T @ V + s.P.T @ W)}


@claim("adv-dp-d-realify-false", kind="id", sizes=ALL)
def d_realify_false(s):
    V, W = s.A @ s.X, s.A @ s.P
    F = lambda u: u.tr(u.realify(u.X, u.P).T @ u.realify(u.X, u.P))
    return {"v": s.d(F, {"X": V, "P": W}) - 4 * s.tr(s.X.T @ V)}


@claim("adv-dp-d-Y-true", kind="id", sizes=ALL)
def d_Y_true(s):
    return {"v": s.d(lambda u: u.tr(u.Y.T @ u.A @ u.Y), {"Y": s.A @ s.Y}) - 2 * s.tr(s.Y.T @ s.A @ s.A @ s.Y)}


@claim("adv-dp-d-Y-false", kind="id", sizes=ALL)
def d_Y_false(s):
    return {"v": s.d(lambda u: u.tr(u.Y.T @ u.A @ u.Y), {"Y": s.A @ s.Y}) - s.tr(s.Y.T @ s.A @ s.A @ s.Y)}


@claim("adv-dp-d-Y-ignored-false", kind="id", sizes=ALL)
def d_Y_ignored(s):
    """d tr(Y^T A Y) along a flow that moves Y (and X) is 0 (false: 2 tr(Y^T A Y))."""
    return {"v": s.d(lambda u: u.tr(u.Y.T @ u.A @ u.Y), {"Y": s.Y, "X": s.A @ s.X})}


@claim("adv-dp-d-pow-true", kind="id", sizes=ALL)
def d_pow_true(s):
    c = lambda u: u.tr(u.X.T @ u.A @ u.X) + u.lam
    dc = 2 * s.tr(s.X.T @ s.A @ s.A @ s.X)
    return {"v": s.d(lambda u: c(u) ** -2, {"X": s.A @ s.X}) + 2 * c(s) ** -3 * dc}


@claim("adv-dp-d-pow-false", kind="id", sizes=ALL)
def d_pow_false(s):
    c = lambda u: u.tr(u.X.T @ u.A @ u.X) + u.lam
    dc = 2 * s.tr(s.X.T @ s.A @ s.A @ s.X)
    return {"v": s.d(lambda u: c(u) ** -2, {"X": s.A @ s.X}) + 2 * c(s) ** -2 * dc}


@claim("adv-dp-grad-div-true", kind="id", sizes=ALL)
def grad_div_true(s):
    HX, HP = s.gradient(lambda u: u.tr(u.X.T @ u.A @ u.X) / (u.tr(u.P.T @ u.P) + u.lam))
    den = s.tr(s.P.T @ s.P) + s.lam
    return {"HX": HX - 2 * (s.A @ s.X) / den, "HP": HP + 2 * s.tr(s.X.T @ s.A @ s.X) * s.P / (den * den)}


@claim("adv-dp-grad-div-false", kind="id", sizes=ALL)
def grad_div_false(s):
    HX, HP = s.gradient(lambda u: u.tr(u.X.T @ u.A @ u.X) / (u.tr(u.P.T @ u.P) + u.lam))
    den = s.tr(s.P.T @ s.P) + s.lam
    return {"HX": HX - 2 * (s.A @ s.X) / den, "HP": HP}


@claim("adv-dp-grad-matdiv-true", kind="id", sizes=ALL)
def grad_matdiv_true(s):
    HX, HP = s.gradient(lambda u: u.tr((u.X / (u.tr(u.P.T @ u.P) + u.lam)).T @ u.A @ u.X))
    den = s.tr(s.P.T @ s.P) + s.lam
    return {"HX": HX - 2 * (s.A @ s.X) / den, "HP": HP + 2 * s.tr(s.X.T @ s.A @ s.X) * s.P / (den * den)}


@claim("adv-dp-grad-killing-rect-true", kind="id", sizes=ALL)
def grad_killing_rect_true(s):
    HX, HP = s.gradient(lambda u: u.killing(u.X, u.P.T @ u.A))
    # -1/2 tr(X P^T A): d/dX = -1/2 (P^T A)^T = -1/2 A P ; d/dP = -1/2 A X
    return {"HX": HX + (s.A @ s.P) * s.q(1, 2), "HP": HP + (s.A @ s.X) * s.q(1, 2)}


@claim("adv-dp-grad-killing-rect-false", kind="id", sizes=ALL)
def grad_killing_rect_false(s):
    HX, HP = s.gradient(lambda u: u.killing(u.X, u.P.T @ u.A))
    return {"HX": HX - (s.A @ s.P) * s.q(1, 2), "HP": HP - (s.A @ s.X) * s.q(1, 2)}


@claim("adv-dp-pg-inverse-of-y", kind="id", sizes=ALL)
def pg_invy(s):
    """The gradient on gl(n) of y -> tr((I + y)^-1) is that of y -> -tr(y) (false: only at y = 0; no
    polynomial, refused)."""
    G = polynomial_gradient(s, lambda t, y: t.tr((t.In + y).inv()), s.xi, "gl", "n")
    H = polynomial_gradient(s, lambda t, y: -t.tr(y), s.xi, "gl", "n")
    return {"v": G - H}


@claim("adv-dp-pg-degree-seven", kind="id", sizes=ALL)
def pg_deg7(s):
    """The gradient on gl(n) of y -> tr(y^7) is 0 (false; a degree above the step's cap: refused)."""
    def f(t, y):
        M = y
        for _ in range(6):
            M = M @ y
        return t.tr(M)
    return {"v": polynomial_gradient(s, f, s.xi, "gl", "n")}


@claim("adv-dp-pg-scaled-true", kind="id", sizes=ALL)
def pg_scaled(s):
    """The gradient of y -> λ⁹ tr(y²) is λ⁹ times that of tr(y²) (true: the step's degree is the point's,
    not the parameters')."""
    return {"v": polynomial_gradient(s, lambda t, y: t.lam ** 9 * t.tr(y @ y), s.xi, "gl", "n")
            - s.lam ** 9 * polynomial_gradient(s, lambda t, y: t.tr(y @ y), s.xi, "gl", "n")}
