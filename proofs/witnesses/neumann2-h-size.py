"""The proof of Theorem 7.1 sets h = Psi(X_0, P_0) and v = X_0 X_0^T and works with h + v in gl(n);
Psi(X_0, P_0) = X_0^T P_0 - P_0^T X_0 is r x r and v is n x n, so for r < n the sum is not defined.
The correction: h = Phi(X_0, P_0) = P_0 X_0^T - X_0 P_0^T, n x n, as in the proof of Lemma 6.2; its block
X_0^T h X_0 is Psi(X_0, P_0), which is 0 on Psi^{-1}(0)."""
import sympy as sp

KIND = "count"
CHECK = "size of h = Ψ(X₀, P₀) = size of v"
SIZE = (3, 2)


def counts():
    X = sp.Matrix([[1, 0], [0, 1], [0, 0]])    # X^T X = I_2
    P = sp.Matrix([[0, 1], [-1, 0], [1, 2]])   # X^T P + P^T X = 0: a point of T*V(3, 2) with Psi != 0
    Psi = lambda X, P: X.T * P - P.T * X       # noqa: E731
    Phi = lambda X, P: P * X.T - X * P.T       # noqa: E731
    assert X.T * Phi(X, P) * X == Psi(X, P) != sp.zeros(2, 2)     # the block h_1 of Phi is Psi
    P0 = (sp.eye(3) - X * X.T) * P             # a point of Psi^{-1}(0) over X
    assert Psi(X, P0) == sp.zeros(2, 2) and X.T * Phi(X, P0) * X == sp.zeros(2, 2)   # there h_1 = 0
    v = X * X.T
    return {"computed": Psi(X, P0).shape[0], "printed": v.shape[0], "corrected": v.shape[0],
            "corrected_computed": Phi(X, P0).shape[0],
            "meaning": "the size of h, against the size n of v = X0 X0^T it is added to"}
