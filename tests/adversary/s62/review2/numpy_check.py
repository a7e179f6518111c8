# ruff: noqa: F841, E702
"""Plain numpy truth at random points of T*V (X^T X = I, X^T P + P^T X = 0; both components at r = n)."""
import numpy as np

rng = np.random.default_rng(62)


def point(n, r, comp=0):
    Q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    if (np.linalg.det(Q) > 0) != (comp == 0):
        Q[:, 0] *= -1
    X = Q[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r))
    P = X @ W + Z
    A = rng.standard_normal((n, n)); A = A + A.T
    assert np.allclose(X.T @ X, np.eye(r)) and np.allclose(X.T @ P + P.T @ X, 0)
    return X, P, A


def xdot(X, P):
    S = X.T @ P
    return P - X @ (S + S.T) / 2


out = {}
for (n, r) in [(3, 1), (3, 2)]:
    X, P, A = point(n, r)
    out[f"ds-false-depth33 ({n},{r}) |X1 - I|"] = np.abs(X[:r, :r] - np.eye(r)).max()
    out[f"pd2 XtP ({n},{r})"] = np.abs(X.T @ P).max()
    out[f"pd2 XXt - I ({n},{r})"] = np.abs(X @ X.T - np.eye(n)).max()
X, P, A = point(3, 2)
e = 1e-6
f = lambda X, P: np.trace(xdot(X, P).T @ A @ X)
d = (f(X, P + e * A @ X) - f(X, P - e * A @ X)) / (2 * e)
K = X.T @ A @ X
out["tw-dA-false d"] = d
out["tw-dA-true residual"] = d - (np.trace(X.T @ A @ A @ X) - np.trace(K @ K))
g = lambda X, P: np.trace(xdot(X, P).T @ X)
out["tw-d-trace-true d"] = (g(X, P + e * X) - g(X, P - e * X)) / (2 * e)
for comp in (0, 1):
    X, P, A = point(3, 3, comp)
    I = np.eye(3)
    out[f"rank X-I, X+I, diag (3,3) comp {comp}"] = (np.linalg.matrix_rank(X - I), np.linalg.matrix_rank(X + I),
                                                    np.linalg.matrix_rank(np.block([[X - I, 0 * I], [0 * I, X + I]])))
    X, P, A = point(2, 2, comp)
    out[f"rank X+I (2,2) comp {comp}"] = np.linalg.matrix_rank(X + np.eye(2))
for k, v in out.items():
    print(k, v)
