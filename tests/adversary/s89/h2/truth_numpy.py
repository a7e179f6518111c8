# ruff: noqa: E702
"""Independent truth (numpy only, no stiefelsym): random points of T*V(n, r): X with orthonormal columns (QR),
P = X W + X⊥ B with W skew (so XᵀP + PᵀX = 0), A = diag(a) with random a, λ random, F random."""
import numpy as np
rng = np.random.default_rng(89)

def point(n, r):
    Q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X, Xp = Q[:, :r], Q[:, r:]
    W = rng.standard_normal((r, r)); W = W - W.T
    P = X @ W + Xp @ rng.standard_normal((n - r, r))
    a = rng.standard_normal(n); A = np.diag(a)
    return X, P, A, a

def show(name, f, sizes):
    vals = []
    for n, r in sizes:
        X, P, A, a = point(n, r)
        assert np.allclose(X.T @ X, np.eye(r)) and np.allclose(X.T @ P + P.T @ X, 0)
        vals.append(f"({n},{r}): {float(np.max(np.abs(np.atleast_1d(f(X, P, A, a, n, r))))):.3e}")
    print(f"{name:24s}", "  ".join(vals))

lam = 0.37
R = lambda A, n: np.linalg.inv(lam * np.eye(n) - A)
Fm = {}
S_all = [(2, 1), (3, 1), (3, 2), (3, 3)]
S_lt = [(2, 1), (3, 1), (3, 2)]
S_r1 = [(2, 1), (3, 1)]
S_r2 = [(2, 2), (3, 2), (4, 2)]
print("max |residual| at one random point per size (0 up to ~1e-15: TRUE there; else FALSE)")
show("XX^T - I_n", lambda X, P, A, a, n, r: X @ X.T - np.eye(n), S_all)
show("X^T X - I_r", lambda X, P, A, a, n, r: X.T @ X - np.eye(r), S_all)
show("X^T P + P^T X", lambda X, P, A, a, n, r: X.T @ P + P.T @ X, S_all)
show("X^T P", lambda X, P, A, a, n, r: X.T @ P, S_all)
show("tr P^T P", lambda X, P, A, a, n, r: np.trace(P.T @ P), [(1, 1)] + S_all)
show("X11^2 - 1", lambda X, P, A, a, n, r: X[0, 0] ** 2 - 1, S_r1)
show("top(X) - I_r", lambda X, P, A, a, n, r: X[:r, :] - np.eye(r), S_lt)
show("tr X^TAX - a1", lambda X, P, A, a, n, r: np.trace(X.T @ A @ X) - a[0], S_r1)
show("tr A - sum a", lambda X, P, A, a, n, r: np.trace(A) - a.sum(), S_all)
def fresh(X, P, A, a, n, r):
    F = rng.standard_normal((n, n)); return np.trace(X.T @ F @ X) - F[0, 0]
show("x^T F x - F11", fresh, S_r1)
show("|row1 X|^2 - 1", lambda X, P, A, a, n, r: X[0, :] @ X[0, :] - 1, S_lt)
show("x^T R x - R11", lambda X, P, A, a, n, r: np.trace(X.T @ R(A, n) @ X) - R(A, n)[0, 0], S_r1)
show("(X^TAX)_12", lambda X, P, A, a, n, r: (X.T @ A @ X)[0, 1], S_r2)
show("(P^TP)_12", lambda X, P, A, a, n, r: (P.T @ P)[0, 1], S_r2)
show("(X^TP)_11", lambda X, P, A, a, n, r: (X.T @ P)[0, 0], S_all)
def psi(X, P, A, a, n, r):
    Psi = X.T @ P - P.T @ X; return Psi[0, 1] ** 2 - np.trace(Psi.T @ Psi) / 2
show("Psi12^2 - tr/2", psi, S_r2)
def psi_f(X, P, A, a, n, r):
    Psi = X.T @ P - P.T @ X; return Psi[0, 1] - np.trace(Psi.T @ Psi) / 2
show("Psi12 - tr/2", psi_f, S_r2)
show("Phi_12", lambda X, P, A, a, n, r: (P @ X.T - X @ P.T)[0, 1], S_r1)
show("A11 - a2", lambda X, P, A, a, n, r: A[0, 0] - a[1], S_lt)
print("by hand: (c+1)t - ct = t = tr PᵀP (> 0 at n >= 2); 2^-1100 t, 2^-2000 t: nonzero where t is; "
      "Fraction(2)t - 2t = 0; Fraction(3)t - t = 2t; Fraction.from_float(0.1) = 3602879701896397/2^55 exactly.")
