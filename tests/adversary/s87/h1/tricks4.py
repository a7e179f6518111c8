"""s87h1 tricks, fourth file: statements true on one component of V(n, n) = O(n) only.

 (det is taken of X as the n×n matrix of its entries, s.mat(...): det(s, s.X) is refused, X: R^r -> R^n.)
 s87h1k-det-plus (FALSE: det X = −1 on the other component of O(n)): det X = 1 at r = n.
 s87h1k-det-minus (FALSE): det X = −1 at r = n.
 s87h1k-det-square (TRUE): (det X)² = 1 at r = n.
 s87h1k-n0-ne-coincide (FALSE off Ψ⁻¹(0), for r ≥ 2): the Dirac flows of H_neum,0 and H_neum,−½ have the same Ẋ
   on all of T*V (they coincide only on Ψ⁻¹(0); Ẋ₀ − Ẋ_E = −XPᵀX = XK).
"""
from stiefelsym import admissible, claim, det

def _sq(s):
    """X as the square matrix of its entries (the form the engine asks for det at r = n)."""
    return s.mat([[s.X[i, j] for j in range(s.r)] for i in range(s.n)], ("n", "n"))


RN = admissible(n_max=4, where=lambda n, r: r == n, condition="r = n")


@claim("s87h1k-det-plus", kind="id", section="7", sizes=RN)
def det_plus(s):
    """det X = 1 (FALSE on the second component)."""
    return {"det X - 1": det(s, _sq(s)) - 1}


@claim("s87h1k-det-minus", kind="id", section="7", sizes=RN)
def det_minus(s):
    """det X = −1 (FALSE)."""
    return {"det X + 1": det(s, _sq(s)) + 1}


@claim("s87h1k-det-square", kind="id", section="7", sizes=RN)
def det_square(s):
    """(det X)² = 1 (TRUE)."""
    d = det(s, _sq(s))
    return {"det^2 - 1": d * d - 1}


def H_N0(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_NE(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s87h1k-n0-ne-coincide", kind="id", section="7", sizes=admissible(n_max=4))
def n0_ne(s):
    """Ẋ of (N0_XP2) = Ẋ of (NE_XP) on T*V (FALSE for r ≥ 2)."""
    return {"Xdot0 - XdotE": s.dirac_flow(H_N0).Xdot - s.dirac_flow(H_NE).Xdot}
