# ruff: noqa: E702
"""Truth for T22, T23 (numpy only)."""
import numpy as np
rng = np.random.default_rng(3)
def comm(a, b): return a@b - b@a
def skew(m): return (m - m.T)/2
def symm(m): return (m + m.T)/2
for n in range(2, 6):
    a = rng.standard_normal(n); A = np.diag(a)
    h = skew(rng.standard_normal((n, n)))
    gl = [np.eye(n*n)[k].reshape(n, n) for k in range(n*n)]
    for name, hh in (("generic h", h), ("x = 0", 0*h)):
        F = lambda y: comm(A, symm(y)) + comm(A, skew(y)) - comm(hh, symm(y))
        M = np.array([F(y).ravel() for y in gl]).T
        print(f"T22 n={n} {name}: rank {np.linalg.matrix_rank(M, tol=1e-9)} (n^2-n = {n*n-n})")
for n in range(1, 6):
    for r in range(1, n+1):
        X, _ = np.linalg.qr(rng.standard_normal((n, n))); X = X[:, :r]
        Z = rng.standard_normal((n, r)); S = X.T@Z; P = Z - X@(S+S.T)/2
        Q = np.eye(r); Q[0, 0] = -1
        Th = lambda X, P: P@X.T - X@P.T + X@X.T
        Ps = lambda X, P: X.T@P - P.T@X
        print(f"T23 ({n},{r}) Theta(XQ,PQ)-Theta = {np.abs(Th(X@Q, P@Q)-Th(X, P)).max():.1e}; twin Psi diff = {np.abs(Ps(X@Q, P@Q)-Ps(X, P)).max():.1e}")
