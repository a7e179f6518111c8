"""Round 8: the component bits at r = n read through elementary() and det() (power traces, no entry read), ranks
whose generic value differs between the components of O(n) x O(n), and divisions and ranks on the reduced exact
charts (the normal part (I − XXᵀ)[0; Z2], onto the normal space where the top r x r block of X is invertible)."""
from stiefelsym import Rank, admissible, claim, det, elementary

SQ2 = admissible(n_min=2, n_max=2, r_is_n=True)
SQ3 = admissible(n_min=3, n_max=3, r_is_n=True)


@claim("adv-s38-e2-e1", kind="id", sizes=SQ3)
def e2_e1(s):
    """e₂(M) = e₁(M) for M = XᵀY in O(3): true on SO(3) only (false on the mixed components)."""
    e = elementary(s, s.X.T @ s.Y, 3)
    return {"e": e[2] - e[1]}


@claim("adv-s38-e2-e1-true", kind="id", sizes=SQ3)
def e2_e1_true(s):
    """e₂(M) = e₁(M)·det M for M = XᵀY in O(3) (true, control)."""
    e = elementary(s, s.X.T @ s.Y, 3)
    return {"e": e[2] - e[1] * e[3]}


@claim("adv-s38-e2-square", kind="id", sizes=SQ2)
def e2_square(s):
    """e₂(M) = e₂(M)² for M = XᵀY at r = n = 2, i.e. det M = 1 (false)."""
    e = elementary(s, s.X.T @ s.Y, 2)
    return {"d": e[2] - e[2] * e[2]}


@claim("adv-s38-det-gx-gy", kind="id", sizes=SQ2)
def det_gx_gy(s):
    """det(GX) = det(GY) for a generic r x n matrix G at r = n = 2, i.e. det X = det Y (false)."""
    G = s.generic("g", "r", "n")
    return {"d": det(s, G @ s.X) - det(s, G @ s.Y)}


@claim("adv-s38-det-x", kind="id", sizes=SQ2)
def det_x(s):
    """det X = 1 at r = n = 2 through det() of X itself (false; X is n x r: its trace is refused)."""
    return {"d": det(s, s.X) - 1}


@claim("adv-s38-pf-mixed", kind="id", sizes=SQ2)
def pf_mixed(s):
    """Pf(MW'Mᵀ) = Pf(W') for M = XᵀY, W' = YᵀQ at r = n = 2, read at the entry (0, 1) of ℝʳ (false:
    Pf(MW'Mᵀ) = det M · Pf W')."""
    M = s.X.T @ s.Y
    W = s.Y.T @ s.Q
    return {"pf": (M @ W @ M.T)[0, 1] - W[0, 1]}


@claim("adv-s38-pf-squared-true", kind="id", sizes=SQ2)
def pf_squared_true(s):
    """Pf(MW'Mᵀ)² = Pf(W')² for M = XᵀY, W' = YᵀQ at r = n = 2 (true, control)."""
    M = s.X.T @ s.Y
    W = s.Y.T @ s.Q
    V = M @ W @ M.T
    return {"pf": V[0, 1] * V[0, 1] - W[0, 1] * W[0, 1]}


@claim("adv-s38-cross-product", kind="id", sizes=SQ3)
def cross_product(s):
    """The first entry of the cross product of the first two columns of M = XᵀY is M₁₃ at n = 3 (false: the
    cross product is det M times the third column)."""
    M = s.X.T @ s.Y
    return {"x": (M[1, 0] * M[2, 1] - M[2, 0] * M[1, 1]) - M[0, 2]}


@claim("adv-s38-rank-mixed", kind="dim", sizes=SQ2)
def rank_mixed(s):
    """XᵀY + I has rank 2 at a generic point (r = n = 2): false where XᵀY is a reflection (rank 1)."""
    return {"r": Rank(s.X.T @ s.Y + s.Ir, 2)}


@claim("adv-s38-rank-mixed-low", kind="dim", sizes=SQ2)
def rank_mixed_low(s):
    """XᵀY + I has rank 1 at a generic point (r = n = 2): false where XᵀY is a rotation (rank 2)."""
    return {"r": Rank(s.X.T @ s.Y + s.Ir, 1)}


@claim("adv-s38-rank-minus", kind="dim", sizes=SQ3)
def rank_minus(s):
    """XᵀY − I has rank 2 at a generic point (r = n = 3): false on the mixed components (rank 3)."""
    return {"r": Rank(s.X.T @ s.Y - s.Ir, 2)}


@claim("adv-s38-rank-top", kind="dim", sizes=admissible(n_min=3, n_max=4, r_min=2, r_max=2))
def rank_top(s):
    """The top 2 x 2 block of X has rank 2 at every point (false: singular where the reduced chart's normal part
    is not onto, e.g. X = [0; I] at n = 4)."""
    return {"r": Rank(s.X[0:2, 0:2], 2, generic=False)}


@claim("adv-s38-rank-normal", kind="dim", sizes=admissible(n_min=4, n_max=4, r_min=2, r_max=2))
def rank_normal(s):
    """(I − XXᵀ)P has rank 2 at every point of T*V(4, 2) (false: P = XW)."""
    return {"r": Rank((s.In - s.X @ s.X.T) @ s.P, 2, generic=False)}


@claim("adv-s38-rank-bottom", kind="dim", sizes=admissible(n_min=4, n_max=4, r_min=2, r_max=2))
def rank_bottom(s):
    """The bottom 2 x 2 block of the normal part (I − XXᵀ)P has rank 2 at every point (false)."""
    N = (s.In - s.X @ s.X.T) @ s.P
    return {"r": Rank(N[2:4, 0:2], 2, generic=False)}


@claim("adv-s38-div-top", kind="id", sizes=admissible(n_min=3, n_max=4, r_min=2, r_max=2))
def div_top(s):
    """d·(1/d) = 1 for d = det of the top 2 x 2 block of X: true as a rational function (defined wherever the
    block is invertible, the set the reduced chart's normal part is onto), as a resolvent is."""
    d = det(s, s.X[0:2, 0:2])
    return {"d": d * (1 / d) - 1}
