"""Round of stop 55: Inverse and RightInverse statements whose op or inv reads A⁻¹.

x ↦ A⁻¹x is invertible exactly where A is; "invertible at every point of T*V" is a statement for every A of the
system, and the standard realization's A is any symmetric matrix (a singular one included).  The identities
op(inv(y)) = y and inv(op(x)) = x hold as rational functions of the entries of A, so they said nothing at
det A = 0, and every method passed these before.  In the metric realization A is positive definite, so there
A⁻¹ is a constant of the system and the statement is true."""
from stiefelsym import Inverse, RightInverse, admissible, claim

SIZES = admissible(n_max=3)


@claim("adv-s55-inv-ainv", kind="id", sizes=SIZES)
def times_a_inverse(s):
    """False for singular A: x ↦ A⁻¹x on R^{n×n}, inverted by y ↦ Ay."""
    return {"inv": Inverse(lambda t, x: t.Ainv @ x, lambda t, y: t.A @ y, on="R^{n×n}")}


@claim("adv-s55-inv-ainv-congruence", kind="id", sizes=SIZES)
def congruence_by_a_inverse(s):
    """False for singular A: x ↦ A⁻¹xA⁻¹ on Sym(n), inverted by y ↦ AyA."""
    return {"inv": Inverse(lambda t, x: t.Ainv @ x @ t.Ainv, lambda t, y: t.A @ y @ t.A, on="Sym(n)")}


@claim("adv-s55-rinv-ainv", kind="id", sizes=SIZES)
def onto_by_a_inverse(s):
    """False for singular A: x ↦ XᵀA⁻¹x maps R^{n×r} onto R^{r×r}, with right inverse y ↦ AXy."""
    return {"onto": RightInverse(lambda t, x: t.X.T @ t.Ainv @ x, lambda t, y: t.A @ t.X @ y, on="R^{n×r}",
                                 to="R^{r×r}")}


@claim("adv-s55-inv-ainv-hidden", kind="id", sizes=SIZES)
def a_inverse_inside_a_product(s):
    """False for singular A: x ↦ (A⁻¹ + A⁻¹)x/2 on R^{n×n} (A⁻¹ below a sum), inverted by y ↦ Ay."""
    return {"inv": Inverse(lambda t, x: (t.Ainv + t.Ainv) @ x / 2, lambda t, y: t.A @ y, on="R^{n×n}")}


@claim("adv-s55-inv-ainv-metric", kind="id", sizes=SIZES, realization="metric")
def times_a_inverse_metric(s):
    """True (control): in the metric realization A is positive definite, and x ↦ A⁻¹x is invertible."""
    return {"inv": Inverse(lambda t, x: t.Ainv @ x, lambda t, y: t.A @ y, on="R^{n×n}")}


@claim("adv-s55-inv-constant", kind="id", sizes=SIZES)
def times_two(s):
    """True (control): x ↦ 2x on R^{n×n}, inverted by y ↦ y/2."""
    return {"inv": Inverse(lambda t, x: x * 2, lambda t, y: y / 2, on="R^{n×n}")}
