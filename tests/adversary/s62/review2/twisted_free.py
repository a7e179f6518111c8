"""Twisted (magnetic) flows inside derivatives and brackets, for the dimension-free method (and exact at (3,2))."""
from stiefelsym import admissible, claim
from stiefelsym import twisted

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def HE(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def tX(t):
    return t.tr(twisted.flow(t, HE)["X"].T @ t.X)


@claim("tw-d-trace-true", kind="id", sizes=R2)
def d_trace_true(s):
    """TRUE: tr(Xdot^T X) = tr(P^T X) = 0 on T*V, so its derivative along the rotation (X eta, P eta) is 0... the
    derivative of tr(P^T X) along (X eta, P eta) is tr(eta^T P^T X eta) = tr(P^T X) = 0."""
    return {"d": s.d(tX, {"X": s.X @ s.eta, "P": s.P @ s.eta})}


@claim("tw-d-trace-false", kind="id", sizes=R2)
def d_trace_false(s):
    """TRUE after all (numpy: tr(Xdot^T X) = 0 wherever X^T X = I, and (0, X) keeps X^T X = I); named -false by
    mistake, kept as a control."""
    return {"d": s.d(tX, {"P": s.X})}


@claim("tw-bracket-false", kind="id", sizes=R2)
def bracket_false(s):
    """TRUE after all (tr(Xdot^T X) vanishes on T*V, so its Dirac bracket does); named -false by mistake."""
    return {"b": s.bracket(tX, lambda t: t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.P.T @ t.P))}


def tA(t):
    return t.tr(twisted.flow(t, HE)["X"].T @ t.A @ t.X)


@claim("tw-dA-true", kind="id", sizes=R2)
def dA_true(s):
    """TRUE: d tr(Xdot^T A X) along (0, AX) = tr(X^T A^2 X) - tr((X^T A X)^2)."""
    K = s.X.T @ s.A @ s.X
    return {"d": s.d(tA, {"P": s.A @ s.X}) - (s.tr(s.X.T @ s.A @ s.A @ s.X) - s.tr(K @ K))}


@claim("tw-dA-false", kind="id", sizes=R2)
def dA_false(s):
    """FALSE: d tr(Xdot^T A X) along (0, AX) = 0."""
    return {"d": s.d(tA, {"P": s.A @ s.X})}
