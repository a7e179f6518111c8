# ruff: noqa
"""Independent truth of the statements of this review (numpy): ranks and identities at random points of T*V(n, r),
and the counts of §8 against (5) §6.  Run: python truth.py"""
import numpy as np

rng = np.random.default_rng(7)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    return X, P


rk = np.linalg.matrix_rank
for n, r in [(4, 2), (3, 3), (4, 1), (4, 3)]:
    X, P = point(n, r)
    print(f"({n},{r}) rank XX^T = {rk(X @ X.T)} (r = {r}); rank X = {rk(X)}; rank (X+P) = {rk(X + P)}; "
          f"rank P = {rk(P)}; min sv of (X+P)^T X = {np.linalg.svd((X + P).T @ X)[1].min():.3f}; "
          f"tr X^TX - r = {np.trace(X.T @ X) - r:.1e}; |XX^TX - X| = {np.abs(X @ X.T @ X - X).max():.1e}; "
          f"|XX^T - I| = {np.abs(X @ X.T - np.eye(n)).max():.2f}")
    S = rng.standard_normal((n - r, n - r)); S = S + S.T
    print(f"      rank of a generic symmetric (n-r)x(n-r) = {rk(S) if n > r else 0}; tr I_(n-r) - 2 = {n - r - 2}")
# P = 0 is a point of T*V: rank P = 0 there, so "rank P = r at every point" is false
print("P = 0 is tangent (X^T 0 + 0^T X = 0): rank 0 < r")
# §8 count against (5) §6
for n in range(1, 8):
    for r in range(1, n + 1):
        N = sum(n - l for l in range(1, r + 1))
        twol = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
        dimTV = 2 * (n * r - r * (r + 1) // 2)
        leaf = dimTV - r * (r - 1) // 2 - r // 2     # dim T*V - dim SO(r) - rank SO(r): a reduced space
        assert leaf == twol, (n, r, leaf, twol)
        assert (2 * N > twol) == (r >= 2) and 2 * N >= twol, (n, r)
print("(5) §6 equals dim T*V - dim SO(r) - rank SO(r) for n <= 7; 2N > 2l exactly when r >= 2, 2N = 2l at r = 1")
