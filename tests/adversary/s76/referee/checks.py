"""Small numeric checks behind SLIPS.md (numpy only; not part of the test suite).

Run: python checks.py   (prints residuals; every line should say True)
"""
import numpy as np

rng = np.random.default_rng(1)
n, r = 6, 3


def stiefel_point():
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    P = rng.standard_normal((n, r))
    P = P - X @ (X.T @ P + P.T @ X) / 2  # X^T P + P^T X = 0
    return X, P


# S20 (l.2562): double Neumann integral.  On X = Y, Xdot = Ydot = P the printed
# X^T Ydot - Y^T Xdot vanishes identically, the Noether momentum X^T Ydot - Xdot^T Y is Psi.
X, P = stiefel_point()
printed = X.T @ P - X.T @ P
intended = X.T @ P - P.T @ X
print("S20 printed integral = 0 on the Neumann subfamily:", np.allclose(printed, 0))
print("S20 intended integral = Psi there, Psi != 0:", np.allclose(intended, X.T @ P - P.T @ X)
      and not np.allclose(intended, 0))

# general double-Neumann data: X^T Y = I, Xdot^T Y + X^T Ydot = 0
A = np.diag(rng.standard_normal(n))
X = rng.standard_normal((n, r)); Y = rng.standard_normal((n, r)); Y = Y @ np.linalg.inv(X.T @ Y)
Xd = 0.3 * rng.standard_normal((n, r)); Yd = 0.3 * rng.standard_normal((n, r))
# project Yd so that Xd^T Y + X^T Yd = 0 (solve for a correction X M)
Yd = Yd - X @ np.linalg.solve(X.T @ X, Xd.T @ Y + X.T @ Yd)
print("double data on constraint:", np.allclose(X.T @ Y, np.eye(r)), np.allclose(Xd.T @ Y + X.T @ Yd, 0))
M_printed = X.T @ Yd - Y.T @ Xd
M_noether = X.T @ Yd - Xd.T @ Y
print("S20 printed integral is symmetric (only r(r+1)/2 components):", np.allclose(M_printed, M_printed.T))
print("S20 Noether momentum is a general r x r matrix:", not np.allclose(M_noether, M_noether.T))


def rhs(state):
    X, Y, Xd, Yd = state
    L = X.T @ A @ Y - Xd.T @ Yd
    return [Xd, Yd, -A @ X + X @ L.T, -A @ Y + Y @ L]


def rk4(state, h):
    k1 = rhs(state)
    k2 = rhs([s + h / 2 * k for s, k in zip(state, k1)])
    k3 = rhs([s + h / 2 * k for s, k in zip(state, k2)])
    k4 = rhs([s + h * k for s, k in zip(state, k3)])
    return [s + h / 6 * (a + 2 * b + 2 * c + d) for s, a, b, c, d in zip(state, k1, k2, k3, k4)]


st = [X, Y, Xd, Yd]
for _ in range(500):
    st = rk4(st, 1e-3)
X1, Y1, Xd1, Yd1 = st
scale = 1 + np.abs(M_noether).max()
print("S20 both conserved along (3) §10 (relative drift < 1e-8, t = 0.5):",
      np.abs(X1.T @ Yd1 - Y1.T @ Xd1 - M_printed).max() / scale < 1e-8,
      np.abs(X1.T @ Yd1 - Xd1.T @ Y1 - M_noether).max() / scale < 1e-8)

# S3/S5/S13 (l.768, 1012, 1780): at r = n the Neumann potential is constant.
Xn, _ = np.linalg.qr(rng.standard_normal((n, n)))
print("S5 potential constant at r = n:", np.isclose(np.trace(Xn.T @ A @ Xn), np.trace(A)))

# S10 (l.1397, 1432): dim ker Lambda_{1,-1}(h+v) = n at a generic point of Theta(T*V).
X, P = stiefel_point()
h = P @ X.T - X @ P.T; v = X @ X.T
so = [(np.eye(n)[:, [i]] @ np.eye(n)[[j], :] - np.eye(n)[:, [j]] @ np.eye(n)[[i], :])
      for i in range(n) for j in range(i + 1, n)]
sym = [(np.eye(n)[:, [i]] @ np.eye(n)[[j], :] + np.eye(n)[:, [j]] @ np.eye(n)[[i], :]) / (1 + (i == j))
       for i in range(n) for j in range(i, n)]
basis = [(x, 0 * x) for x in so] + [(0 * y, y) for y in sym]
ip = lambda a, b: -0.5 * np.trace(a @ b)
br = lambda a, b: a @ b - b @ a


def lam_1m1(u, w):  # (12) §6
    (xi, eta), (ze, th) = u, w
    return -ip(h, br(eta, th)) + ip(A, br(xi, th) + br(eta, ze))


G = np.array([[lam_1m1(u, w) for w in basis] for u in basis])
print("S10 dim ker Lambda_{1,-1} = n:", len(basis) - np.linalg.matrix_rank(G, tol=1e-9) == n)
