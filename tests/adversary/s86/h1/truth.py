# ruff: noqa: E701, E702
"""Independent truths (numpy and fractions only; no stiefelsym).  Random points of T*V(n, r): X with orthonormal
columns (QR), P = X W + (I - X X^T) Z with W skew (so X^T P + P^T X = 0), A = diag(a)."""
from fractions import Fraction

import numpy as np

rng = np.random.default_rng(1)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    A = np.diag(rng.standard_normal(n))
    xi = rng.standard_normal((n, n)); xi = xi - xi.T
    return X, P, A, xi


nrm = lambda M: float(np.max(np.abs(M)))   # noqa: E731
for n, r in [(2, 2), (3, 1), (3, 2), (4, 1), (4, 2)]:
    X, P, A, xi = point(n, r)
    I_n, I_r = np.eye(n), np.eye(r)
    out = {
        "tangent X^T P + P^T X": nrm(X.T @ P + P.T @ X),
        "X^T X - I_r (true)": nrm(X.T @ X - I_r),
        "X X^T - I_n (false at r<n)": nrm(X @ X.T - I_n),
        "X^T P - P^T X (b8-skewf: 0 iff r=1)": nrm(X.T @ P - P.T @ X),
        "tr(X0^T X) - r (pa-x0/pb-x0block/pb-dir: false)": abs(np.trace(X[:r, :r]) - r),
        "(XX^T)_11 - 1 (pa-idslice at r=1: false)": abs((X @ X.T)[0, 0] - 1),
        "tr(X^T A X) n - tr(A) r (pb-sym: false)": abs(np.trace(X.T @ A @ X) * n - np.trace(A) * r),
    }
    if r == 2:
        D = np.diag([1.0, 2.0])
        M = X.T @ A @ X
        out["[D, X^T A X] (pa-diagcomm: false)"] = nrm(D @ M - M @ D)
        out["A_12 (pa-adiag-t: true)"] = abs(A[0, 1])
        out["A_11 - A_22 (pa-adiag-f: false)"] = abs(A[0, 0] - A[1, 1])
    if r == 1 and n > 2:
        out["[xi, X X^T] (pb-xi: false)"] = nrm(xi @ X @ X.T - X @ X.T @ xi)
    print((n, r), {k: f"{v:.3g}" for k, v in out.items()})

# exact-constant claims (X^T X = I_r holds exactly, so tr(X^T X) = r):
C = 2 ** 30
print("pa-cancel-f residual = r(1+C)^2 - r(1+C)^2 - 1 =", -1, " (tr((X^TX + C I)^2) = r (1 + C)^2 since X^TX = I)")
c = Fraction(1, 2 ** 80)
print("pa-tiny-f: (1 + 2^-80) X - X = 2^-80 X, nonzero coefficient", c)
print("pa-huge-f: 2^1200 r - 2^1200 r - 2^1190 =", -(2 ** 1190) != 0)
print("pb-fromfloat-f: Fraction(0.1) - 1/10 =", Fraction(0.1) - Fraction(1, 10))
print("pb-fromfloat-t: Fraction(0.1) == 3602879701896397/2^55:", Fraction(0.1) == Fraction(3602879701896397, 2 ** 55))
cu = Fraction(1, 2 ** 1100)
print("pb-underflow-t: (cA)(X/c) - AX = 0 exactly (c cancels); pb-underflow-f adds -c X, c =", float(cu), "> 0 exactly:", cu > 0)
print("pb-chain-t: 2^-1074 * 2^-1074 * 2^2148 =", Fraction(1, 2 ** 1074) * Fraction(1, 2 ** 1074) * 2 ** 2148)
