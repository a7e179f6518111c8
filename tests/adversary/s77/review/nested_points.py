"""s77 review: derivatives at the claim's problem at another point (twisted.at_point) whose point moves with an
enclosing derivative's function; and the fixed-size scenes' level confusion (a flow of an innermost derivative
read from the outermost function's scene).  -true: TRUE, -false: FALSE."""
from stiefelsym import admissible, claim
from stiefelsym.twisted import at_point

SZ = admissible(n_max=3)


def quad(u):
    return u.tr(u.X.T @ u.A @ u.X)


def norm(u):
    return u.tr(u.X.T @ u.X)


@claim("s77r-atpoint-moving-true", kind="id", sizes=SZ)
def atpoint_moving_true(s):
    """at the point (X_t, P_t): d_V tr(XᵀAX) = 2tr(VᵀAX_t); along U: 2tr(VᵀAU)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: at_point(s, t.X, t.P).d(quad, {"X": V}), {"X": U})
    return {"w": got - s.tr(V.T @ s.A @ U) * 2}


@claim("s77r-atpoint-moving-false", kind="id", sizes=SZ)
def atpoint_moving_false(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: at_point(s, t.X, t.P).d(quad, {"X": V}), {"X": U})
    return {"w": got}


@claim("s77r-atpoint-euler-true", kind="id", sizes=SZ)
def atpoint_euler_true(s):
    """at (X_t, P_t): d_{X} tr(XᵀX) along the point's own X = 2tr(X_tᵀX_t); along U: 4tr(UᵀX)."""
    U = s.fresh("n", "r")

    def f(t):
        q = at_point(s, t.X, t.P)
        return q.d(norm, {"X": t.X})
    got = s.d(f, {"X": U})
    return {"w": got - s.tr(U.T @ s.X) * 4}


@claim("s77r-atpoint-euler-false", kind="id", sizes=SZ)
def atpoint_euler_false(s):
    """FALSE: 0 (the value 2r of T*V taken as constant)."""
    U = s.fresh("n", "r")

    def f(t):
        q = at_point(s, t.X, t.P)
        return q.d(norm, {"X": t.X})
    got = s.d(f, {"X": U})
    return {"w": got}


# -- the fixed-size scenes' level confusion (see FINDINGS.md, F1)
def _three(s, U, V):
    return s.d(lambda t: t.d(lambda u: u.d(quad, {"X": t.X}), {"X": V}), {"X": U})


@claim("s77r-level-true", kind="id", sizes=SZ)
def level_true(s):
    """innermost y ↦ dF(y)(x_t) = 2tr(x_tᵀAy); middle along V at y = x_t: 2tr(x_tᵀAV); outer along U:
    2tr(UᵀAV).  TRUE (free proves; exact, modular, rational, float say fails)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _three(s, U, V) - s.tr(U.T @ s.A @ V) * 2}


@claim("s77r-level-false", kind="id", sizes=SZ)
def level_false(s):
    """FALSE: 2tr(UᵀAU) (V confused with U).  Exact, modular, rational, float PROVE/CHECK it."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _three(s, U, V) - s.tr(U.T @ s.A @ U) * 2}


@claim("s77r-level-ax-true", kind="id", sizes=SZ)
def level_ax_true(s):
    """innermost along A x_t: 2tr(UᵀA²V) at the end.  TRUE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.d(quad, {"X": t.A @ t.X}), {"X": V}), {"X": U})
    return {"w": got - s.tr(U.T @ s.A @ s.A @ V) * 2}


@claim("s77r-level-ax-false", kind="id", sizes=SZ)
def level_ax_false(s):
    """FALSE: 2tr(UᵀA²U)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.d(quad, {"X": t.A @ t.X}), {"X": V}), {"X": U})
    return {"w": got - s.tr(U.T @ s.A @ s.A @ U) * 2}
