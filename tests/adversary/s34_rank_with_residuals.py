"""Fourth round (AM): the confirmation of a `numeric` verdict (methods._confirm_numeric) keeps the float verdict
when the modular run at exact points is not `fails` and has checks, e.g. `undecided` for a rank at every point.
A true residual next to a false rank statement: float and ball must not pass the claim on its residuals."""
from stiefelsym import Rank, admissible, claim

S = admissible(n_min=3, n_max=3, r_min=2, r_max=2)


@claim("adv-s34-rank-every-point", paper="t", kind="id", sizes=S)
def every_point(s):
    """False: Xᵀ X = I_r, and Xᵀ A X has rank r at every point (it is singular where XᵀAX is)."""
    return {"XtX": s.X.T @ s.X - s.identity(s.r), "rank": Rank(s.X.T @ s.A @ s.X, 2, generic=False)}


@claim("adv-s34-rank-too-high", paper="t", kind="id", sizes=S)
def too_high(s):
    """False: Xᵀ X = I_r, and X Xᵀ has rank n."""
    return {"XtX": s.X.T @ s.X - s.identity(s.r), "rank": Rank(s.X @ s.X.T, 3)}


@claim("adv-s34-rank-too-low", paper="t", kind="id", sizes=S)
def too_low(s):
    """False: Xᵀ X = I_r, and X Xᵀ has rank 1."""
    return {"XtX": s.X.T @ s.X - s.identity(s.r), "rank": Rank(s.X @ s.X.T, 1)}
