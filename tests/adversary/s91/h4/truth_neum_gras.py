# ruff: noqa
"""Numpy truth of (neum-gras) at random points of T*V, and of the changed statements the tricks make the catalog
function compute (first Plücker coordinate of the right-hand side shifted by c*X[n,1], or by c*X[n,1]^3)."""
import itertools, sys
import numpy as np
sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from common import random_point


def pl(cols):
    M = np.column_stack(cols)
    n, k = M.shape
    return np.array([np.linalg.det(M[list(I), :]) for I in itertools.combinations(range(n), k)])


def residual(n, r, rng):
    X, P = random_point(n, r, rng)
    a = rng.standard_normal(n); A = np.diag(a)
    Xd = P
    Lam = X.T @ A @ X - Xd.T @ Xd
    Xdd = -A @ X + X @ Lam
    E = [X[:, i] for i in range(r)]; V = [Xd[:, i] for i in range(r)]; W = [Xdd[:, i] for i in range(r)]
    AE = [(A @ X)[:, i] for i in range(r)]
    rep = lambda ch: [ch.get(i, E[i]) for i in range(r)]
    second = sum(pl(rep({i: W[i]})) for i in range(r)) + 2 * sum(pl(rep({i: V[i], j: V[j]})) for i, j in itertools.combinations(range(r), 2)) if r > 1 else pl(rep({0: W[0]}))
    lam = np.trace(X.T @ A @ X - Xd.T @ Xd)
    rhs = lam * pl(E) - sum(pl(rep({i: AE[i]})) for i in range(r)) + (2 * sum(pl(rep({i: V[i], j: V[j]})) for i, j in itertools.combinations(range(r), 2)) if r > 1 else 0)
    return np.max(np.abs(second - rhs)), X


rng = np.random.default_rng(7)
for n, r in [(3, 1), (3, 2), (4, 2), (4, 3)]:
    res, X = residual(n, r, rng)
    print(f"({n},{r}) printed (neum-gras): max|residual| = {res:.2e} (true);  X[n,1] = {X[n-1,0]:.3f}, "
          f"so a residual shifted by c*X[n,1] or c*X[n,1]^3 (c != 0) is nonzero: FALSE")
