from stiefelsym import admissible, claim
from stiefelsym.twisted import at_point

SZ = admissible(n_max=3)


def quad(u):
    return u.tr(u.X.T @ u.A @ u.X)


@claim("o78-atpoint-t-true", kind="id", sizes=SZ)
def t_true(s):
    """at the point (X_t, P_t) taken from t: d_U d_V tr(XᵀAX) = 2tr(VᵀAU)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: at_point(t, t.X, t.P).d(quad, {"X": V}), {"X": U})
    return {"w": got - s.tr(V.T @ s.A @ U) * 2}


@claim("o78-atpoint-t-false", kind="id", sizes=SZ, expect="fails", erratum="a false twin")
def t_false(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: at_point(t, t.X, t.P).d(quad, {"X": V}), {"X": U})
    return {"w": got - s.tr(V.T @ s.A @ V) * 2}


@claim("o78-atpoint-outer-true", kind="id", sizes=SZ)
def outer_true(s):
    """a value of the enclosing scene s given to at_point(t, ...): a constant of t's level, so
    d_U [t -> d_V tr(XᵀAX) at (X_s, P_s)] = 0... taken at s's point: d_V = 2tr(VᵀAX_s), constant in t."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: at_point(t, s.X, s.P).d(quad, {"X": V}), {"X": U})
    return {"w": got}


@claim("o78-atpoint-outer-false", kind="id", sizes=SZ, expect="fails", erratum="a false twin")
def outer_false(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: at_point(t, s.X, s.P).d(quad, {"X": V}), {"X": U})
    return {"w": got - s.tr(V.T @ s.A @ U) * 2}
