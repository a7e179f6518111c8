"""Values of an enclosing function's scene (fewer dual levels) inside a nested derivative: as a flow, as a scalar
factor, as a matrix factor, inside the flow of the innermost derivative.  The review's F1 (s77/review/nested_points.py)
found the first confused with the inner level; these are the other doors.  Docstrings state the truth."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def quad(t):
    return t.tr(t.X.T @ t.A @ t.X)


def sq(t):
    return t.tr(t.X.T @ t.X)


def _scalar_factor(s, U, V):
    # outer along U of: d/dε₂ [ c_t · sq(u) ] along V, c_t = quad(t) a value of the outer level
    return s.d(lambda t: t.d(lambda u: sq(u) * quad(t), {"X": V}), {"X": U})


@claim("s77-level-scalar-true", kind="id", sizes=SZ)
def level_scalar_true(s):
    """= 2tr(UᵀAX)·2tr(XᵀV) + tr(XᵀAX)·2tr(UᵀV): TRUE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    X, A = s.X, s.A
    want = s.tr(U.T @ A @ X) * 2 * (s.tr(X.T @ V) * 2) + s.tr(X.T @ A @ X) * (s.tr(U.T @ V) * 2)
    return {"w": _scalar_factor(s, U, V) - want}


@claim("s77-level-scalar-false", kind="id", sizes=SZ)
def level_scalar_false(s):
    """The same with the inner level's part of c_t added (2tr(VᵀAX)·2tr(XᵀU) more): FALSE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    X, A = s.X, s.A
    want = s.tr(U.T @ A @ X) * 2 * (s.tr(X.T @ V) * 2) + s.tr(X.T @ A @ X) * (s.tr(U.T @ V) * 2)
    return {"w": _scalar_factor(s, U, V) - want - s.tr(V.T @ A @ X) * 2 * (s.tr(X.T @ U) * 2)}


def _matrix_flow(s, U, V):
    # the innermost flow is u.X scaled by a value c_t of the outer level: d quad(w) along c_t·u.X at w = u-point
    return s.d(lambda t: t.d(lambda u: u.d(quad, {"X": u.X * sq(t)}), {"X": V}), {"X": U})


@claim("s77-level-matrix-flow-true", kind="id", sizes=SZ)
def level_matrix_flow_true(s):
    """innermost: 2 c_t tr(u.XᵀA u.X); middle along V: 4 c_t tr(XₜᵀAV); outer along U (c_t = tr(XₜᵀXₜ), dc = 2tr(XᵀU)):
    8tr(XᵀU)tr(XᵀAV) + 4 tr(XᵀX) tr(UᵀAV): TRUE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    X, A = s.X, s.A
    want = s.tr(X.T @ U) * 8 * s.tr(X.T @ A @ V) + s.tr(X.T @ X) * 4 * s.tr(U.T @ A @ V)
    return {"w": _matrix_flow(s, U, V) - want}


@claim("s77-level-matrix-flow-false", kind="id", sizes=SZ)
def level_matrix_flow_false(s):
    """The same without the derivative of c_t: FALSE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    X, A = s.X, s.A
    return {"w": _matrix_flow(s, U, V) - s.tr(X.T @ X) * 4 * s.tr(U.T @ A @ V)}


def _outer_flow_value(s, U, V):
    # the middle derivative's flow is a value of the outer level: d/dε₂ sq(u) along t.X (V unused)
    return s.d(lambda t: t.d(sq, {"X": t.X}), {"X": U})


@claim("s77-level-middle-flow-true", kind="id", sizes=SZ)
def level_middle_flow_true(s):
    """d/dε₁ [2tr(XₜᵀXₜ)] = 4tr(XᵀU): TRUE (two levels only: the flow is of the enclosing scene itself)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _outer_flow_value(s, U, V) - s.tr(s.X.T @ U) * 4}


@claim("s77-level-sibling-flow", kind="id", sizes=SZ)
def level_sibling_flow(s):
    """A flow made in a sibling function's scene, smuggled out through a list and used inside another derivative:
    refused (no verdict), never confused."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    kept = []

    def grab(t):
        kept.append(t.X)
        return sq(t)
    s.d(grab, {"X": U})
    return {"w": s.d(lambda t: t.d(sq, {"X": kept[0]}), {"X": V}) - s.tr(s.X.T @ V) * 0}
