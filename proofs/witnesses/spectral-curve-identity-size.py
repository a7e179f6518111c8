"""The spectral curve of L*_neum(lambda) is printed |a(lambda) L*_neum(lambda) - w I_n| = w^{2r} + ...;
L*_neum(lambda) of (LA3) is 2r x 2r, so the determinant is defined only when n = 2r.
The correction: I_{2r}."""
import sympy as sp

KIND = "count"
CHECK = "size of L*_neum = size of I_n"
SIZE = (1, 1)


def counts():
    n, r = SIZE
    lam, a1 = sp.Rational(5), sp.Rational(2)
    X = sp.Matrix([[1]])                       # a point of V(1, 1): X^T X = 1
    P = sp.zeros(n, r)                         # X^T P + P^T X = 0
    R = (lam * sp.eye(n) - sp.diag(a1)).inv()  # (lambda I_n - A)^{-1}
    # (LA3): [[-X^T R P, -X^T R X], [I_r + P^T R P, P^T R X]]
    L = sp.Matrix(sp.BlockMatrix([[-(X.T * R * P), -(X.T * R * X)], [sp.eye(r) + P.T * R * P, P.T * R * X]]))
    return {"computed": L.shape[0], "printed": n, "corrected": 2 * r,
            "meaning": "the rows of L*_neum(lambda), against the size of the identity matrix"}
