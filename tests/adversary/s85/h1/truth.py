"""Independent truths for h1's stop-85 sweep: numpy and fractions only (no stiefelsym)."""
from fractions import Fraction

import numpy as np

rng = np.random.default_rng(85)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    P0 = rng.standard_normal((n, r))
    S = X.T @ P0
    P = P0 - X @ (S + S.T) / 2          # XᵀP + PᵀX = 0
    A = np.diag(rng.standard_normal(n))
    return X, P, A


def skew(m):
    G = rng.standard_normal((m, m))
    return G - G.T


out = []
# F: the divisors of the poles files: k = 1 − 2r/(n + r) = (n − r)/(n + r) is 0 exactly at r = n
for n in range(1, 6):
    for r in range(1, n + 1):
        k = 1 - Fraction(2 * r, n + r)
        k5 = 1 - Fraction(2, r + 1)
        k4 = 1 - Fraction(8, n + 4)
        if k == 0 or k5 == 0 or k4 == 0:
            out.append(f"pole: (n,r)=({n},{r}) k={k} k5={k5} k4={k4}")
for n, r in [(3, 1), (3, 2), (3, 3), (4, 2), (4, 3), (4, 4)]:
    X, P, A = point(n, r)
    Psi = X.T @ P - P.T @ X
    eta = skew(r)
    out.append(f"({n},{r}) |XᵀX−I|={np.abs(X.T @ X - np.eye(r)).max():.1e} |XXᵀ−I|={np.abs(X @ X.T - np.eye(n)).max():.2f} "
               f"|XᵀP|={np.abs(X.T @ P).max():.2f} |[Ψ,η]|={np.abs(Psi @ eta - eta @ Psi).max():.2f} "
               f"|Ψ²−½trΨ²I|={np.abs(Psi @ Psi - np.trace(Psi @ Psi) / 2 * np.eye(r)).max():.2f} "
               + (f"(XᵀAX)01={(X.T @ A @ X)[0, 1]:.3f} Ψ01={Psi[0, 1]:.3f} (XᵀP)10={(X.T @ P)[1, 0]:.3f} " if r >= 2 else "")
               + f"|X/3−X/2|={np.abs(X / 3 - X / 2).max():.3f} tr(XᵀX)/3−r/2={np.trace(X.T @ X) / 3 - r / 2:.3f}")
print("\n".join(out))
