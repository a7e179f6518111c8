"""In the proof of Theorem 8.2 the tangency equation of the 2r-planes to the cone Q(lambda*) sums
(e_1^...^e_r^p_i)^2 over i = 1, ..., n, but the momenta p_1, ..., p_r are the r columns of P (cond_XP).
The correction: i = 1, ..., r (and 1 <= i < j <= r), as in (2r-integrals)."""
import sympy as sp

KIND = "count"
CHECK = "number of momenta pᵢ"
SIZE = (2, 1)


def counts():
    n, r = SIZE
    X = sp.Matrix([[1], [0]])                 # X^T X = I_r: a point of V(2, 1)
    P = sp.Matrix([[0], [1]])                 # X^T P + P^T X = 0 (cond_XP): a cotangent vector at X
    assert X.T * X == sp.eye(r) and X.T * P + P.T * X == sp.zeros(r, r)
    momenta = [P[:, i] for i in range(P.shape[1])]          # p_1, ..., p_r: the columns of P
    printed = len(range(1, n + 1))            # the printed range i = 1, ..., n
    corrected = len(range(1, r + 1))          # the corrected range i = 1, ..., r
    return {"computed": len(momenta), "printed": printed, "corrected": corrected,
            "meaning": "the momenta p_i (columns of P), against the range of i in the tangency equation"}
