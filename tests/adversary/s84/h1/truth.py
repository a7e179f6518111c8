"""Independent truth (numpy + fractions, no stiefelsym) for h1's claims."""
from fractions import Fraction as F
import numpy as np

rng = np.random.default_rng(1)


def point(n, r):
    X = np.linalg.qr(rng.standard_normal((n, n)))[0][:, :r]
    Z = rng.standard_normal((n, r))
    S = X.T @ Z
    P = Z - X @ (S + S.T) / 2          # XᵀP + PᵀX = 0
    return X, P


print("== division divisors at each size (exact rationals): 0 means the claim divides by 0 there")
for n in range(2, 5):
    for r in range(1, n + 1):
        k_rn = F(1, n + r) - F(1, 2 * n)
        k_2r = F(1, n + r) - F(1, 3 * r)
        k_nest = F(1, n) + F(1, r) - F(4, n + r)
        k_ok = F(1, n) + F(1, r) - F(2, n + r)
        k0 = F(1, n + r) - F(1, n + 2 * r) - F(r, (n + r) * (n + 2 * r))
        print(f"(n,r)=({n},{r}) k_rn={k_rn} k_2r={k_2r} k_nested={k_nest} k_nested_ok={k_ok} k_zero={k0} "
              f"r-1={r-1} 1/r-1={F(1, r) - 1} 2/n-1={F(2, n) - 1}")

print("== traces, seal claims, ranks at random points")
for n in range(2, 5):
    for r in range(1, n + 1):
        X, P = point(n, r)
        Phi = P @ X.T - X @ P.T
        print(f"(n,r)=({n},{r}) |XᵀXP+PᵀX|={np.abs(X.T @ P + P.T @ X).max():.1e} tr(XᵀX)-r={np.trace(X.T @ X) - r:.1e} "
              f"|P+P|={np.abs(2 * P).max():.3f} |XᵀX+I|={np.abs(X.T @ X + np.eye(r)).max():.3f} "
              f"rank X={np.linalg.matrix_rank(X)} rank Φ={np.linalg.matrix_rank(Phi)} |ΦX|={np.abs(Phi @ X).max():.3f}")
