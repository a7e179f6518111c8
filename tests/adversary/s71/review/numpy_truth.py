# ruff: noqa
"""Independent truth of the statements used here (numpy, a random point of T*V(n, r)).
Run: python numpy_truth.py"""
import numpy as np

rng = np.random.default_rng(1)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    Z = rng.standard_normal((n, r))
    W = rng.standard_normal((r, r)); W = W - W.T
    P = X @ W + (np.eye(n) - X @ X.T) @ Z          # XᵀP + PᵀX = 0
    return X, P


for n, r in [(2, 1), (2, 2), (3, 1), (3, 2), (3, 3)]:
    X, P = point(n, r)
    assert np.allclose(X.T @ X, np.eye(r)) and np.allclose(X.T @ P + P.T @ X, 0)
    print(f"({n},{r}) |XᵀP| = {np.abs(X.T @ P).max():.3f}  (XᵀP = 0 false iff r >= 2)")
    # s71-c-radial: d/de tr((X+eX)ᵀ(X+eX)) at e = 0 is 2 tr XᵀX = 2r
    e = 1e-6
    f = lambda Y: np.trace(Y.T @ Y)
    print(f"      radial derivative {(f(X + e * X) - f(X - e * X)) / (2 * e):.6f} = 2r = {2 * r}")
