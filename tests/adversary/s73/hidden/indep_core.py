# ruff: noqa: E701, E702, F841 - a numpy check written compactly, kept as its author wrote it
"""Plain numpy machinery for indep.py (no stiefelsym import): points of T*V(n, r), canonical and Dirac
brackets and flows (gradients by complex step, exact to rounding for rational functions)."""
import numpy as np

H_CS = 1e-30


def point(n, r, rng, comp=0):
    G = rng.standard_normal((n, n))
    Q, R = np.linalg.qr(G)
    Q = Q * np.sign(np.diag(R))
    if np.linalg.det(Q) < 0:
        Q[:, 0] *= -1
    if comp == 1:
        Q[:, -1] *= -1       # the other component of O(n) (matters at r = n)
    X = Q[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    return X, P


def A_of(n, rng):
    return np.diag(np.sort(rng.uniform(-3, 3, n)) + np.arange(n) * 0.3)


def grad(f, X, P):
    """(∂f/∂X, ∂f/∂P) of a scalar f(X, P) by complex step."""
    n, r = X.shape
    gX = np.zeros((n, r)); gP = np.zeros((n, r))
    for i in range(n):
        for j in range(r):
            E = np.zeros((n, r), dtype=complex); E[i, j] = 1j * H_CS
            gX[i, j] = np.imag(f(X + E, P)) / H_CS
            gP[i, j] = np.imag(f(X, P + E)) / H_CS
    return gX, gP


def dirv(F, X, P, V):
    """d/dε F(X + εV_X, P + εV_P) at ε = 0 (complex step); F scalar or array."""
    VX, VP = V
    return np.imag(F(X + 1j * H_CS * VX, P + 1j * H_CS * VP)) / H_CS


def constraints(X, P):
    r = X.shape[1]
    iu = np.triu_indices(r)
    A1 = X.T @ X - np.eye(r)
    A2 = X.T @ P + P.T @ X
    return [(lambda k: (lambda X, P: (X.T @ X)[iu[0][k], iu[1][k]]))(k) for k in range(len(iu[0]))] + \
           [(lambda k: (lambda X, P: (X.T @ P + P.T @ X)[iu[0][k], iu[1][k]]))(k) for k in range(len(iu[0]))]


def can(gf, gg):
    return np.sum(gf[0] * gg[1]) - np.sum(gf[1] * gg[0])


def dirac_data(X, P):
    Fs = constraints(X, P)
    gF = [grad(F, X, P) for F in Fs]
    C = np.array([[can(a, b) for b in gF] for a in gF])
    return gF, np.linalg.inv(C)


def bracket(f, g, X, P, dd=None):
    gF, Ci = dd or dirac_data(X, P)
    gf, gg = grad(f, X, P), grad(g, X, P)
    fF = np.array([can(gf, a) for a in gF]); Fg = np.array([can(a, gg) for a in gF])
    return can(gf, gg) - fF @ Ci @ Fg


def flow(H, X, P, dd=None):
    """The Dirac flow (Ẋ, Ṗ) of H: df(v) = {f, H}_D."""
    gF, Ci = dd or dirac_data(X, P)
    gH = grad(H, X, P)
    FH = np.array([can(a, gH) for a in gF])
    w = Ci @ FH
    # X_G = (∂G/∂P, −∂G/∂X)
    VX = gH[1] - sum(wi * a[1] for wi, a in zip(w, gF))
    VP = -gH[0] + sum(wi * a[0] for wi, a in zip(w, gF))
    return VX, VP


def phi(X, P):
    return P @ X.T - X @ P.T


def psi(X, P):
    return X.T @ P - P.T @ X


def jac(F, X, P):
    """Jacobian of a flattened array function F(X, P) in the 2nr coordinates (X row by row, then P)."""
    n, r = X.shape
    cols = []
    for which in (0, 1):
        for i in range(n):
            for j in range(r):
                E = np.zeros((n, r), dtype=complex); E[i, j] = 1j * H_CS
                v = F(X + E, P) if which == 0 else F(X, P + E)
                cols.append(np.imag(np.ravel(v)) / H_CS)
    return np.array(cols).T


def mrank(M, tol=1e-8):
    s = np.linalg.svd(M, compute_uv=False)
    return int(np.sum(s > tol * max(1.0, s[0])))
