# ruff: noqa
"""Independent truth of the q64 claims (numpy at random points of T*V, of W(n, r) and by hand); prints
claim, sizes, max |residual|.  A residual above 1e-8 means the statement is false there."""
import numpy as np

rng = np.random.default_rng(64)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    P = X @ W + (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r))
    return X, P


def cpoint(n, r):
    Z, _ = np.linalg.qr(rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n)))
    Z = Z[:, :r]
    w = rng.standard_normal((r, r)) + 1j * rng.standard_normal((r, r)); w = w - w.conj().T
    Zd = Z @ w + (np.eye(n) - Z @ Z.conj().T) @ (rng.standard_normal((n, r)) + 1j * rng.standard_normal((n, r)))
    return Z, Zd


def realify(M):
    return np.block([[M.real, -M.imag], [M.imag, M.real]])


SIZES = [(n, r) for n in range(1, 5) for r in range(1, n + 1)]
CHECKS = {
    "q64-md-a / q64-plain-false / texp/* (XᵀX = 2I)": lambda n, r: (lambda X, P: X.T @ X - 2 * np.eye(r))(*point(n, r)),
    "q64-md-b / q64-plain-true (XᵀX = I)": lambda n, r: (lambda X, P: X.T @ X - np.eye(r))(*point(n, r)),
    "q64-q-tangent-true": lambda n, r: (lambda Y, Q: Y.T @ Q + Q.T @ Y)(*point(n, r)),
    "q64-q-horizontal-false (r<n)": lambda n, r: (lambda Y, Q: Q - Y @ Y.T @ Q)(*point(n, r)),
    "q64-q-vertical-false": lambda n, r: (lambda Y, Q: Y.T @ Q)(*point(n, r)),
    "q64-xy-false": lambda n, r: (lambda X, Y: X.T @ Y - Y.T @ X)(point(n, r)[0], point(n, r)[0]),
    "q64-xy-qp-false": lambda n, r: (lambda a, b: np.trace(a[0].T @ b[1]) + np.trace(b[0].T @ a[1]))(point(n, r), point(n, r)),
    "q64-z-unitary-true": lambda n, r: (lambda Z, Zd: realify(Z).T @ realify(Z) - np.eye(2 * r))(*cpoint(n, r)),
    "q64-z-tangent-true": lambda n, r: (lambda Z, Zd: realify(Z).T @ realify(Zd) + realify(Zd).T @ realify(Z))(*cpoint(n, r)),
    "q64-z-horizontal-false (r<n)": lambda n, r: (lambda Z, Zd: Zd - Z @ Z.conj().T @ Zd)(*cpoint(n, r)),
    "q64-z-complex-linear-true": lambda n, r: (lambda M, J: M @ J - J @ M)(realify((lambda Z, Zd: Z.conj().T @ Zd)(*cpoint(n, r))), realify(1j * np.eye(r))),
    "q64-z-real-false": lambda n, r: (lambda Z, Zd: (Z.conj().T @ Zd).imag)(*cpoint(n, r)),
    "q64-z-imtrace-false": lambda n, r: (lambda Z, Zd: np.trace(Z.conj().T @ Zd).imag)(*cpoint(n, r)),
    "q64-z-square-false (r<n) / -true (r=n)": lambda n, r: (lambda Z, Zd: Z @ Z.conj().T - np.eye(n))(*cpoint(n, r)),
    "q64-names-true": lambda n, r: (lambda X, P: (X.T @ P + P.T @ X))(*point(n, r)),
    "q64-names-false (cX = X, c generic)": lambda n, r: (lambda X, P: 1.7 * X - X)(*point(n, r)),
    "q64-sr-* (tr I_r = 1 etc.)": lambda n, r: np.array([r - 1.0]),
    "q64-rin-*: E1E1ᵀ+E2E2ᵀ = I_r": lambda n, r: (np.diag([1.0, 1.0] + [0.0] * (r - 2)) - np.eye(r)) if r >= 2 else np.zeros(1),
    "q64-rin-12-false: X E1E1ᵀ Xᵀ = XXᵀ": lambda n, r: (lambda X, P: X[:, :1] @ X[:, :1].T - X @ X.T)(*point(n, r)),
}


def so_rank(n, r, X, sub=None):
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    cols = []
    for (i, j) in pairs:
        if sub is not None and not (i >= r and j >= r):
            continue
        xi = np.zeros((n, n)); xi[i, j], xi[j, i] = 1, -1
        cols.append((xi @ X).ravel())
    return np.linalg.matrix_rank(np.array(cols).T) if cols else 0


if __name__ == "__main__":
    for name, f in CHECKS.items():
        out = []
        for n, r in SIZES:
            out.append(f"({n},{r}):{np.max(np.abs(f(n, r))):.1e}")
        print(name, " ".join(out))
    for n, r in [(3, 1), (4, 1), (4, 2)]:
        X, _ = point(n, r)
        print(f"q64-kernel-x0-false (true rank) ({n},{r}): rank {so_rank(n, r, X)} vs printed {n*r - r*(r+1)//2};"
              f" q64-kernel-x0-low-false: rank {so_rank(n, r, X, sub=True)} vs printed 0")
