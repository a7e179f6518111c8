"""The paragraph on the Chasles theorem for Manakov flows takes the integrals J_{2l}(lambda) from
|a(lambda) L*_man(lambda) - w I_n| under 2r < n; L*_man(lambda) of (MAN-LA2) is 2r x 2r, so the determinant
is not defined.  The correction: I_{2r}."""
import sympy as sp

KIND = "count"
CHECK = "size of 𝓛*_man = size of Iₙ"
SIZE = (3, 1)


def counts():
    n, r = SIZE
    lam = sp.Rational(7)
    a = [sp.Rational(1), sp.Rational(2), sp.Rational(4)]
    X = sp.Matrix([[1], [0], [0]])             # X^T X = 1
    P = sp.Matrix([[0], [1], [3]])             # X^T P + P^T X = 0
    R = (lam * sp.eye(n) - sp.diag(*a)).inv()  # (lambda I_n - A)^{-1}
    # (MAN-LA2): [[-X^T R P, -X^T R X], [P^T R P, P^T R X]]
    L = sp.Matrix(sp.BlockMatrix([[-(X.T * R * P), -(X.T * R * X)], [P.T * R * P, P.T * R * X]]))
    return {"computed": L.shape[0], "printed": n, "corrected": 2 * r,
            "meaning": "the rows of L*_man(lambda), against the size of the identity matrix"}
