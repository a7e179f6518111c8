"""Stop 83 review (h2): the chart choice when the only look at coordinates is inside a product the reassociated
trace no longer computes (brief item 3), and a join of untyped spaces the reassociation makes stricter.
-t- true, -f- false."""
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_min=1, r_max=3)


def _U(s):
    """An untyped constant 3 x 3 matrix (no side on ℝⁿ when it is made: its look at coordinates is recorded
    where it meets ℝⁿ, here only inside the cancelled products U X Xᵀ − U X Xᵀ)."""
    return s.mat([[1, 0, 0], [0, 0, 0], [0, 0, 0]])


@claim("adv-s83r-t-chart-cancelled-look", paper="adv", kind="id", sizes=S)
def t_chart(s):
    """True everywhere: the untyped E₁₁ meets X only inside a cancelled pair; the rest is covariant."""
    M = s.generic("M", "n", "n")
    U = _U(s)
    XX = s.X @ s.X.T
    y = U @ XX - U @ XX + s.Phi @ s.A
    return {"c": s.tr(M @ y) - s.tr((M @ s.Phi) @ s.A)}


@claim("adv-s83r-f-chart-point-only", paper="adv", kind="id", sizes=S)
def f_chart(s):
    """False in general, true at the equivariant chart's point X = (E_1..E_r): tr(E₁₁ X Xᵀ) = 1 (it is X₁₁² + ...,
    the squared norm of X's first row), here read through the untyped U outside any cancelled pair together with
    a cancelled pair that alone would record it."""
    M = s.generic("M", "n", "n")
    U = _U(s)
    XX = s.X @ s.X.T
    y = U @ XX - U @ XX + s.Phi @ s.A
    return {"c": s.tr(M @ y) - s.tr((M @ s.Phi) @ s.A) + s.killing(U, XX) * (-2) - 1}
