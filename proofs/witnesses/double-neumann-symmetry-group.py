"""After Theorem 10.1 the matrix integral X^T Y' - Y^T X' of the double Neumann system is said to come from the
GL(n, R)-symmetry (X, Y, X', Y') -> (X R^T, Y R^{-1}, X' R^T, Y' R^{-1}).  X and Y are n x r, and R multiplies
them on the right: R is r x r, so the group is GL(r, R), and the integral X^T Y' - Y^T X' is r x r too."""
import sympy as sp

KIND = "count"
CHECK = "columns of X = size of R"
SIZE = (2, 1)


def counts():
    n, r = SIZE
    X = sp.Matrix([[1], [0]])                  # a point of V(2, 1): X^T X = I_1
    Y = sp.Matrix([[0], [1]])
    Xd, Yd = sp.Matrix([[0], [1]]), sp.Matrix([[2], [0]])   # X^T X' + X'^T X = 0, Y^T Y' + Y'^T Y = 0
    R = sp.Matrix([[3]])                       # an element of GL(r, R): X R^T is defined
    integral = lambda X, Y, Xd, Yd: X.T * Yd - Y.T * Xd     # noqa: E731
    moved = (X * R.T, Y * R.inv(), Xd * R.T, Yd * R.inv())
    assert integral(X, Y, Xd, Yd) != sp.zeros(r, r)
    assert integral(*moved) == R * integral(X, Y, Xd, Yd) * R.inv()   # the integral transforms by conjugation
    return {"computed": X.shape[1], "printed": n, "corrected": r,
            "meaning": "the columns of X (the size R must have to act by X R^T), against the size n of GL(n)"}
