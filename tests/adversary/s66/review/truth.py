# ruff: noqa
"""Independent numpy truth of the attempts' statements at random points of T*V(n, r): X^T X = I, X^T P + P^T X = 0."""
import numpy as np
from fractions import Fraction

rng = np.random.default_rng(66)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    A = np.diag(rng.standard_normal(n))
    assert np.allclose(X.T @ X, np.eye(r)) and np.allclose(X.T @ P + P.T @ X, 0)
    return X, P, A


def E(k, i):
    v = np.zeros((k, 1)); v[i, 0] = 1; return v


out = {}
n, r = 4, 2
X, P, A = point(n, r)
S1 = np.diag([-1.0] + [1.0] * (n - 1)); D = np.diag([1.0, 1.0] + [0.0] * (n - 2))
Phi = P @ X.T - X @ P.T
out["c1-refl-trace"] = np.trace(X.T @ S1 @ X) - (r - 2)
out["c1-eig-trace"] = np.trace(X.T @ D @ X) - 2
out["c1-eig-fixes-X"] = np.abs(D @ X - X).max()
out["c1-refl-block"] = np.abs((S1 @ X + X) @ E(r, 0)).max()
out["c1-refl-commutes-XXt"] = np.abs(S1 @ X @ X.T - X @ X.T @ S1).max()
out["c1-refl-Phi"] = np.trace(S1 @ Phi @ S1 @ Phi) - np.trace(Phi @ Phi)
E11 = np.zeros((n, r)); E11[0, 0] = 1
out["c1u-unit-read"] = np.trace(E11.T @ X) - 1
out["c1u-unit-deriv"] = 4 * (X @ X.T @ X)[0, 0] - 4
out["c1u-unit-true2"] = np.trace(E11.T @ (X @ X.T @ X - X))
out["c4-b-reader (alone: X)"] = np.abs(X).max()
out["c8-false X^T P"] = np.abs(X.T @ P).max()
out["c11-true-at-2-only (r=2)"] = np.trace(np.eye(2) - E(2, 0) @ E(2, 0).T) - 1
X1, P1, A1 = point(3, 1)
out["c11-true-at-2-only (r=1)"] = np.trace(np.eye(1) - E(1, 0) @ E(1, 0).T) - 1
out["c11-true-at-1-only (r=2)"] = np.abs(X @ E(2, 0) @ E(2, 0).T @ X.T - X @ X.T).max()
out["c11-true-at-1-only (r=1)"] = np.abs(X1 @ X1.T - X1 @ X1.T).max()
out["c2-frac-of-float coefficient"] = float(Fraction(0.1) - Fraction(1, 10))
lam = 0.37
R = np.linalg.inv(lam * np.eye(3) - A1)
out["c12 c = tr(X^T R X) at a point (vanishes between eigenvalues for some lam)"] = float((X1.T @ R @ X1)[0, 0])
for k, v in out.items():
    print(f"{k:60s} {float(v): .3e}")
