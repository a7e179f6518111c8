# ruff: noqa
"""Numpy truth for g_module_builtins.py: (neum-gras) computed with the changed determinant det'(M) = det(M) +
x^3 * cof_11(M), x = X[n,1] (what the catalog function computes once minor's enumerate is the evil one), at a random
point of T*V: the residual is nonzero (FALSE); at X = X0 it is zero."""
import itertools, sys
import numpy as np
sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from common import random_point


def detp(M, x):
    M = M.copy(); M[0, 0] += x ** 3
    return np.linalg.det(M)


def pl(cols, x):
    M = np.column_stack(cols); n, k = M.shape
    return np.array([detp(M[list(I), :], x) for I in itertools.combinations(range(n), k)])


def resid(X, P, A):
    n, r = X.shape
    Lam = X.T @ A @ X - P.T @ P
    Pd = -A @ X + X @ Lam

    def vel(X, P):
        x = X[n - 1, 0]
        E = [X[:, i] for i in range(r)]
        return sum(pl([P[:, j] if j == i else E[j] for j in range(r)], x) for i in range(r))
    h = 1e-5
    second = (vel(X + h * P, P + h * Pd) - vel(X - h * P, P - h * Pd)) / (2 * h)
    x = X[n - 1, 0]
    E = [X[:, i] for i in range(r)]; V = [P[:, i] for i in range(r)]; AE = [(A @ X)[:, i] for i in range(r)]
    rep = lambda ch: [ch.get(i, E[i]) for i in range(r)]
    lam = np.trace(X.T @ A @ X - P.T @ P)
    rhs = lam * pl(E, x) - sum(pl(rep({i: AE[i]}), x) for i in range(r)) + \
        2 * sum(pl(rep({i: V[i], j: V[j]}), x) for i, j in itertools.combinations(range(r), 2))
    return np.max(np.abs(second - rhs))


rng = np.random.default_rng(3)
for n, r in [(3, 2), (4, 2)]:
    X, P = random_point(n, r, rng); A = np.diag(rng.standard_normal(n))
    print(f"({n},{r}) changed statement at a random point: max|residual| = {resid(X, P, A):.3e}")
    X0 = np.eye(n)[:, :r]; Z = rng.standard_normal((n, r)); W = Z[:r] - Z[:r].T
    P0 = np.vstack([W / 2, Z[r:]])
    print(f"({n},{r}) changed statement at X = X0: max|residual| = {resid(X0, P0, A):.3e}")
