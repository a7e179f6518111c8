"""Round 4b: Inverse statements whose op or inv divides by something that vanishes somewhere.

op(inv(y)) = y and inv(op(x)) = x hold as rational identities, so they prove op invertible only where
every divisor is nonzero.  Each claim says "invertible at every point of T*V", which is false: the
divisor vanishes at some point of T*V (P = 0, tr PᵀP = 1, a singular PᵀP or XᵀAX with A indefinite) or at
some element (x = 0).  None may pass under any method."""
from stiefelsym import Inverse, admissible, claim

SIZES = admissible(n_max=3)


def _norm(t):
    return t.tr(t.P.T @ t.P)


@claim("adv-s34b-inv-div-trace", kind="id", sizes=SIZES)
def times_the_norm_of_p(s):
    """x ↦ tr(PᵀP)·x on Sym(r), inverted by y/tr(PᵀP): not invertible at P = 0."""
    return {"inv": Inverse(lambda t, x: _norm(t) * x, lambda t, y: y / _norm(t), on="Sym(r)")}


@claim("adv-s34b-inv-div-sphere", kind="id", sizes=SIZES)
def times_norm_minus_one(s):
    """ξ ↦ (tr(PᵀP) − 1)·ξ on so(n): not invertible where tr PᵀP = 1."""
    return {"inv": Inverse(lambda t, x: (_norm(t) - 1) * x, lambda t, y: y / (_norm(t) - 1), on="so(n)")}


@claim("adv-s34b-inv-pow", kind="id", sizes=SIZES)
def times_the_norm_squared(s):
    """x ↦ tr(PᵀP)²·x on R^{n×r}, inverted by tr(PᵀP)^-2·y (a negative power)."""
    return {"inv": Inverse(lambda t, x: _norm(t) ** 2 * x, lambda t, y: _norm(t) ** -2 * y, on="R^{n×r}")}


@claim("adv-s34b-inv-congruence-ptp", kind="id", sizes=SIZES)
def congruence_by_ptp(s):
    """x ↦ M x M on Sym(r), M = PᵀP, inverted by M⁻¹ y M⁻¹: singular where rank P < r."""
    def op(t, x):
        M = t.P.T @ t.P
        return M @ x @ M

    def inv(t, y):
        N = (t.P.T @ t.P).inv()
        return N @ y @ N
    return {"inv": Inverse(op, inv, on="Sym(r)")}


@claim("adv-s34b-inv-congruence-xax", kind="id", sizes=SIZES)
def congruence_by_xax(s):
    """x ↦ W x W on R^{r×r}, W = XᵀAX, inverted by W⁻¹ y W⁻¹: singular on V where A is indefinite."""
    def op(t, x):
        W = t.X.T @ t.A @ t.X
        return W @ x @ W

    def inv(t, y):
        N = (t.X.T @ t.A @ t.X).inv()
        return N @ y @ N
    return {"inv": Inverse(op, inv, on="R^{r×r}")}


@claim("adv-s34b-inv-element-inverse", kind="id", sizes=SIZES)
def matrix_inversion(s):
    """x ↦ x⁻¹ on R^{r×r}, its own inverse: undefined at x = 0."""
    return {"inv": Inverse(lambda t, x: x.inv(), lambda t, y: y.inv(), on="R^{r×r}")}


@claim("adv-s34b-inv-element-sphere", kind="id", sizes=SIZES)
def sphere_inversion(s):
    """x ↦ x / tr(x xᵀ) on R^{n×r}, its own inverse: undefined at x = 0."""
    def f(t, x):
        return x / t.tr(x @ x.T)
    return {"inv": Inverse(f, f, on="R^{n×r}")}
