# ruff: noqa
"""numpy truths of the r64 claims at random points of T*V (run with the venv's python)."""
import numpy as np
rng = np.random.default_rng(1)
n, r = 3, 2
X, _ = np.linalg.qr(rng.standard_normal((n, r)))
Z = rng.standard_normal((n, r)); W = rng.standard_normal((r, r)); W = W - W.T
P = X @ W + (np.eye(n) - X @ X.T) @ Z
print("XtX - 2I (r64-tex-*, r64-md-a-false):", np.abs(X.T @ X - 2 * np.eye(r)).max())
c = 2.0 ** 10          # the identity is polynomial in c: c = 2^10 shows it in float64
V = X + c * P
print("cancel-true residual/c^2:", np.abs(V.T @ V - np.eye(r) - c * c * P.T @ P).max() / c**2)
print("cancel-false residual (= |PtP|):", np.abs(V.T @ V - np.eye(r) - (c * c + 1) * P.T @ P).max())
# kernel_component: det(X^T Y) = -1 on mixed pairs of O(2)
Y = np.array([[1, 0], [0, -1.0]]); Xs = np.eye(2)
M = np.diag([np.linalg.det(Xs.T @ Y) - 1, 1]); print("rank on a mixed pair:", np.linalg.matrix_rank(M))
