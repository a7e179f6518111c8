"""Item 1 under float: a non-affine (non-quadratic) part scaled by 10⁻⁶⁰.  Control: a bare residual of 10⁻⁶⁰·tr(XᵀAX)
(FALSE: nonzero).  form_gradient of <G, y> + 10⁻⁶⁰·tr(y³ᵀy...) style cubic on so(n): the engine's sum over a basis is
the gradient of an affine form only; the false twin states the secant sum is the gradient G of the affine part
plus nothing (it is FALSE as a statement about the form: the form is not affine, a wrong-degree form should be
refused, and the claimed value G of 'the gradient' ... see FINDINGS)."""
from fractions import Fraction
from stiefelsym import claim
from stiefelsym.brackets import form_gradient
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SZ = [(2, 1), (3, 2)]
TINY = Fraction(1, 10 ** 60)


@claim("r3-tiny-bare-false", kind="id", sizes=SZ)
def bare_false(s):
    return {"r": s.tr(s.X.T @ s.A @ s.X) * s.q(TINY.numerator, TINY.denominator)}


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


@claim("r3-tiny-el-cubic-false", kind="id", sizes=[(2, 1)])
def el_cubic_false(s):
    """T = tr(ẊᵀẎ) + 10⁻⁶⁰·Ẋ₁₁Ẋ₂₁Ẏ₁₁: not quadratic; FALSE that its accelerations are (D-eq)'s (expected: refused)."""
    z = double_point(s)
    c = s.q(TINY.numerator, TINY.denominator)

    def T(t, v):
        X, Y = v["X"], v["Y"]
        return t.tr(X.T @ Y) + X[0, 0] * X[1, 0] * Y[0, 0] * c
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}


@claim("r3-tiny-form-false", kind="id", sizes=SZ)
def form_false(s):
    """form(y) = <K, y> + 10⁻⁶⁰·tr(y y y) ... on gl(n) (not affine: expected refused); claimed gradient K (FALSE: no
    gradient of a non-affine form, and the basis sum is K + 10⁻⁶⁰·(…) ≠ K)."""
    K = s.generic("K", "n", "n")
    c = s.q(TINY.numerator, TINY.denominator)
    G = form_gradient(s, lambda t, y: t.tr(K @ y) * s.q(-1, 2) + t.tr(y @ y @ y.T) * c, s.zeros(s.n, s.n), "gl", "n")
    return {"G": G - K}
