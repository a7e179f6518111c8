"""The proof of Theorem NEUMANN2 sets h = Psi(X_0, P_0) and v = X_0 X_0^T and works with h + v in gl(n);
Psi(X_0, P_0) = X_0^T P_0 - P_0^T X_0 is r x r and v is n x n, so for r < n the sum is not defined.
The correction: h = Phi(X_0, P_0), n x n, as in the proof of Lemma LEMA1; its block X_0^T h X_0 is
Psi(X_0, P_0) = 0 on Psi^{-1}(0)."""
import sympy as sp

KIND = "count"
CHECK = "size of h = Psi(X0, P0) = size of v"
SIZE = (2, 1)


def counts():
    X0 = sp.Matrix([[1], [0]])                 # X0^T X0 = 1
    P0 = sp.Matrix([[0], [1]])                 # X0^T P0 = 0: a point of Psi^{-1}(0)
    v = X0 * X0.T
    psi = X0.T * P0 - P0.T * X0                # the printed h
    phi = P0 * X0.T - X0 * P0.T                # the corrected h
    assert X0.T * phi * X0 == psi == sp.zeros(1, 1)      # h_1 = Psi(X0, P0) = 0
    return {"computed": psi.shape[0], "printed": v.shape[0], "corrected": v.shape[0],
            "corrected_computed": phi.shape[0],
            "meaning": "the size of h, against the size n of v = X0 X0^T it is added to"}
