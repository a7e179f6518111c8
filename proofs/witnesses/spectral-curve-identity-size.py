"""The spectral curve of L*_neum(lambda) is printed |a(lambda) L*_neum(lambda) - w I_n| = w^{2r} + ...;
L*_neum(lambda) of (LA3) is 2r x 2r, so the determinant is defined only when n = 2r.
The correction: I_{2r}, with which the determinant is monic of degree 2r in w."""
import sympy as sp

KIND = "count"
CHECK = "size of 𝓛*_neum = size of Iₙ"
SIZE = (3, 1)


def counts():
    n, r = SIZE
    lam, w = sp.Rational(7), sp.Symbol("w")
    a = [sp.Rational(1), sp.Rational(2), sp.Rational(4)]
    X = sp.Matrix([[1], [0], [0]])             # X^T X = 1
    P = sp.Matrix([[0], [1], [3]])             # X^T P + P^T X = 0
    R = (lam * sp.eye(n) - sp.diag(*a)).inv()  # (lambda I_n - A)^{-1}
    # (LA3): [[-X^T R P, -X^T R X], [I_r + P^T R P, P^T R X]]
    L = sp.Matrix(sp.BlockMatrix([[-(X.T * R * P), -(X.T * R * X)], [sp.eye(r) + P.T * R * P, P.T * R * X]]))
    a_lam = sp.prod([lam - ai for ai in a])
    curve = sp.expand((a_lam * L - w * sp.eye(L.shape[0])).det())
    assert sp.Poly(curve, w).degree() == 2 * r and sp.Poly(curve, w).coeff_monomial(w) == 0   # I_{2r}: no odd power
    return {"computed": L.shape[0], "printed": n, "corrected": 2 * r,
            "meaning": "the rows of L*_neum(lambda), against the size of the identity matrix"}
