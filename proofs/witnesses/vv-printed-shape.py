"""The matrix V(X, P) of (VV) is called a 2r x (n + r) matrix; its columns e_1, ..., e_r, p_1, ..., p_r
are 2r vectors of R^{n+r}, so it has n + r rows and 2r columns.  The correction: (n + r) x 2r."""
import sympy as sp

KIND = "count"
CHECK = "rows of V"
SIZE = (2, 1)


def counts():
    n, r = SIZE
    X = sp.Matrix([[1], [0]])                  # a point of V(2, 1): X^T X = 1
    P = sp.Matrix([[0], [3]])                  # X^T P + P^T X = 0
    # (VV): the columns e_1..e_r (of X over 0) and p_1..p_r (of P over I_r)
    V = sp.Matrix(sp.BlockMatrix([[X, P], [sp.zeros(r, r), sp.eye(r)]]))
    assert V.rank() == 2 * r                   # the columns span a 2r-plane of R^{n+r}
    return {"computed": V.shape[0], "printed": 2 * r, "corrected": n + r,
            "meaning": "the rows of V(X, P), against the printed 2r x (n + r)"}
