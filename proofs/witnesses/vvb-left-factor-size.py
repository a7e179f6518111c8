"""The proof of Theorem 8.5 multiplies V(X, P) of (VV) on the left by diag(I_{n-r}, B^{-1}), a
square matrix of size (n - r) + r = n; but V(X, P) has n + r rows, so the product is not defined.
The correction: diag(I_n, B^{-1}), of size n + r."""
import sympy as sp

KIND = "count"
CHECK = "rows of V = size of the left factor"
SIZE = (1, 1)


def counts():
    n, r = SIZE
    X = sp.Matrix([[1]])                       # a point of V(1, 1): X^T X = 1
    P = sp.zeros(n, r)                         # X^T P + P^T X = 0
    # (VV): the columns e_1..e_r, p_1..p_r of the (n + r) x 2r matrix [[X, P], [0, I_r]]
    V = sp.Matrix(sp.BlockMatrix([[X, P], [sp.zeros(r, r), sp.eye(r)]]))
    B = sp.Matrix([[2]])                       # any invertible r x r matrix
    printed = sp.diag(sp.eye(n - r), B.inv()) if n > r else B.inv()
    corrected = sp.diag(sp.eye(n), B.inv())
    return {"computed": V.shape[0], "printed": printed.shape[1], "corrected": corrected.shape[1],
            "meaning": "the rows of V(X, P), against the columns of the left factor"}
