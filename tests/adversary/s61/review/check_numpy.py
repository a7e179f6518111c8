# ruff: noqa: E702 (a scratch script of the review: several statements on a line)
"""Independent numpy checks of the truth of the statements probed in this review (random points of T*V)."""
import numpy as np

rng = np.random.default_rng(61)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    Z = rng.standard_normal((n, r))
    W = rng.standard_normal((r, r)); W = W - W.T
    P = X @ W + (np.eye(n) - X @ X.T) @ Z          # X^T P skew
    return X, P


n, r = 4, 2
A = np.diag(rng.standard_normal(n))
ok = {}
X, P = point(n, r)
assert np.allclose(X.T @ X, np.eye(r)) and np.allclose(X.T @ P + P.T @ X, 0)
Psi = X.T @ P - P.T @ X
ok["rr-i-plus-psi TRUE: det(I + Psi) >= 1"] = np.linalg.det(np.eye(r) + Psi) >= 1 - 1e-12
ok["rr-ptp-plus-i TRUE: I + P^T P pos. def."] = np.linalg.eigvalsh(np.eye(r) + P.T @ P).min() > 0
# Neumann flow (standard, kappa = -1/2): Xdot = P, Pdot = -AX + X(X^T A X - P^T P)
Xd = P
Pd = -A @ X + X @ (X.T @ A @ X - P.T @ P)
assert np.allclose(Xd.T @ X + X.T @ Xd, 0) and np.allclose(Xd.T @ P + X.T @ Pd + Pd.T @ X + P.T @ Xd, 0)
Y, Q = point(n, r)
ok["fp-y-const TRUE"] = True          # d/dt tr(Y^T X) = tr(Y^T Xdot) by linearity (Y constant)
ok["fp-y-xdot FALSE: tr(Y^T Xdot) != tr(Y^T X)"] = abs(np.trace(Y.T @ Xd) - np.trace(Y.T @ X)) > 1e-6
ok["fp-scalar-zero FALSE: d/dt tr(X^T A A X) != 0"] = abs(2 * np.trace(Xd.T @ A @ A @ X)) > 1e-6
eps = 1e-6
f = lambda Yv: np.trace(Yv.T @ A @ Yv)
ok["fk-move-Y TRUE"] = abs((f(Y + eps * Q) - f(Y - eps * Q)) / (2 * eps) - 2 * np.trace(Y.T @ A @ Q)) < 1e-6
ok["fk-move-Y-false FALSE"] = abs(2 * np.trace(Y.T @ A @ Q)) > 1e-6
# free geodesic flow H = tr(P^T P)/2: Xdot = P, Pdot = -X P^T P; d/dt (X^T P) = P^T P - X^T X P^T P = 0
ok["tc-bracket-matrix TRUE (as d/dt of X^T P)"] = np.allclose(P.T @ P + X.T @ (-X @ P.T @ P), 0)
ok["tc-d-bracket FALSE: d/dt X^T A X != 0"] = not np.allclose(Xd.T @ A @ X + X.T @ A @ Xd, 0)
ok["nz-* vanish on T*V"] = np.allclose(X.T @ X - np.eye(r), 0) and np.allclose(X.T @ P + P.T @ X, 0)
ok["dm-minus-n TRUE: (-n)X + nX = 0"] = True
for k, v in ok.items():
    print("OK " if v else "BAD", k)
