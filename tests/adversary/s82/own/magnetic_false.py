"""Stop 82's own attempt on the typed magnetic F: the flow of the twisted form with F = J against F = 2J.

The twisted Poisson structure has ε F in the bracket of the momenta; with ε generic, F and 2F give different
flows of H = ½ tr PᵀP + ½ tr XᵀAX wherever the F-term of the flow is nonzero (n ≥ 3 at r = 2: the magnetic term
moves P within the plane of X's columns and out of it).  So "the flows agree" is FALSE there; "F = J given
explicitly is the default F" is TRUE.
"""
from stiefelsym import admissible, claim, twisted

R2 = admissible(n_max=4, n_min=3, r_min=2, r_max=2, condition="r = 2")


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s82own-twice-J-false", kind="id", sizes=R2)
def twice_j(s):
    """FALSE: the flows of F = J and F = 2J agree."""
    J = twisted.magnetic_matrix(s)
    f1, f2 = twisted.flow(s, H, J), twisted.flow(s, H, 2 * J)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("s82own-default-J-true", kind="id", sizes=R2)
def default_j(s):
    """TRUE: F = J given explicitly is the default F."""
    f1, f2 = twisted.flow(s, H, twisted.magnetic_matrix(s)), twisted.flow(s, H)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}
