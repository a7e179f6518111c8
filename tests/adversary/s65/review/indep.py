# ruff: noqa
"""Independent numpy checks of the findings of this review (no stiefelsym)."""
import numpy as np

rng = np.random.default_rng(65)


def point(n, r):
    """A random point of T*V(n, r): XᵀX = I, XᵀP + PᵀX = 0."""
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    return X, P


# 1. discover on flow_mul_p: Xdot = c P, Pdot = -c X PᵀP with c = 2^61 - 1 (a nonzero rational)
n, r = 4, 2
X, P = point(n, r)
A = np.diag(rng.standard_normal(n))
c = 1.0  # the scale does not change which quantities are conserved; c = 2^61 - 1 != 0 over Q
Xd, Pd = c * P, -c * X @ P.T @ P
d = {
    "tr(APPᵀ)": 2 * np.trace(A @ Pd @ P.T),
    "tr(APXᵀ)": np.trace(A @ Pd @ X.T) + np.trace(A @ P @ Xd.T),
    "tr(AXXᵀ)": 2 * np.trace(A @ Xd @ X.T),
    "tr(PPᵀ)": 2 * np.trace(Pd @ P.T),
}
print("1. d/dt along flow_mul_p at a random point of T*V(4,2):")
for k, v in d.items():
    print(f"   {k}: {v:+.3e}")
print("   -> only tr(PPᵀ) is conserved; discover printed dim 5 / 4 independent integrals (exit 0)")

# 2. the headline's "where a correction is registered it was verified": XᵀX = 3 I_r is false on T*V
print("2. XᵀX - 3I at a point of T*V(3,2):", np.abs(X[:3, :2].T @ X[:3, :2]).max() if False else
      np.abs((lambda X: X.T @ X - 3 * np.eye(2))(point(3, 2)[0])).max(), "(nonzero: the correction is false)")
X3, P3 = point(3, 2)
print("   XᵀP + PᵀX on T*V(3,2):", np.abs(X3.T @ P3 + P3.T @ X3).max(), "(0: the 'not' claim fails without a witness point)")

# 3. (XᵀX)⁻¹ = I_r and (3I + XᵀX)⁻¹·4 = I_r hold on T*V (float and ball say inconclusive)
X, P = point(3, 2)
print("3. (XᵀX)^-1 - I:", np.abs(np.linalg.inv(X.T @ X) - np.eye(2)).max(),
      " (3I + XᵀX)^-1·4 - I:", np.abs(np.linalg.inv(3 * np.eye(2) + X.T @ X) * 4 - np.eye(2)).max())
