# ruff: noqa: F841, E702, F401, E731, E741
"""numpy truth of the batch1 claims at random points of T*V (both components of O(n) at r = n)."""
import numpy as np
rng = np.random.default_rng(63)


def point(n, r, flip=False):
    Q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    if flip:
        Q[:, 0] *= -1
    X = Q[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    return X, P, np.diag(rng.standard_normal(n))


X, P, A = point(3, 2)
D = np.diag([1., 1, 0]); S = np.diag([-1., 1, 1])
print("b1-dn-x (FALSE)        |DX - X| =", np.abs(D @ X - X).max())
print("b1-refl-trace (FALSE)  =", np.trace(X.T @ S @ X) - 0)
M, N = X.T @ S @ X, X.T @ A @ X
print("b1-refl-right (FALSE)  =", np.abs(M @ N - N @ M).max())
for n in (2, 3):
    X, P, A = point(n, n); Y, _, _ = point(n, n, flip=True)
    print(f"b1-nz-xxt-sq n={n} (zero) =", np.abs(X @ X.T - np.eye(n)).max(),
          " det(XtY)-1 (mixed comp., nonzero) =", np.linalg.det(X.T @ Y) - 1,
          " det^2-1 (zero) =", np.linalg.det(X.T @ Y) ** 2 - 1)
X, P, A = point(3, 2)
print("b1-lead-square (3,2) FALSE |X X^T - I| =", np.abs(X @ X.T - np.eye(3)).max())
W = rng.standard_normal((3, 2)); G = W.T @ W
K = np.linalg.det(G) * np.eye(3) - W @ (np.linalg.det(G) * np.linalg.inv(G)) @ W.T
print("b1-kernel-sq (3,2) FALSE |K X| =", np.abs(K @ X).max(),
      " b1-kernel-rank TRUE =", np.abs(K @ K @ K * np.trace(K) - K @ K * np.trace(K @ K)).max())
