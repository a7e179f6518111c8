# ruff: noqa: E702
"""Independent numerical truth for the statements the reports' "As traced" texts READ AS (no stiefelsym import).
Random points of T*V(n, r): X = Q-factor of a Gaussian n×r, P = (I − XXᵀ)G + X S (S skew r×r), so XᵀP + PᵀX = 0.
Neumann: Ẋ = P, Ṗ = −AX + XΛ (Λ from d/dt(XᵀP + PᵀX) = 0); geodesic (K = ½ tr PᵀP): Ẋ = P, Ṗ = XΛ₀."""
import numpy as np

rng = np.random.default_rng(1)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    S = rng.standard_normal((r, r)); S = S - S.T
    P = (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r)) + X @ S
    A = np.diag(rng.standard_normal(n))
    return X, P, A


n, r = 4, 2
X, P, A = point(n, r)
print("tangency |XᵀP + PᵀX| =", np.abs(X.T @ P + P.T @ X).max())
# t1: dH/dt along the Neumann flow (the statement as worded): Ẋ = P, Ṗ = −AX + XΛ, Λ sym solves the constraint
Lam = X.T @ A @ X - P.T @ P                      # from 2PᵀP − 2XᵀAX + 2Λ = 0 (Λ symmetric)
Pd = -A @ X + X @ Lam
print("t1 dH/dt along Neumann (statement, TRUE = 0):", np.trace(P.T @ Pd) + np.trace(X.T @ A @ P))
print("t1 dH/dt along geodesic flow (graph, nonzero):", np.trace(X.T @ A @ P) + np.trace(P.T @ (X @ (-P.T @ P))))
print("t2 dK/dt along Neumann (statement, FALSE unless 0):", np.trace(P.T @ Pd))
print("t3 Ṗ_geo − Ṗ_Neu (nonzero):", np.abs(X @ (-P.T @ P) - Pd).max())
X1, P1, _ = point(2, 1)
print("t4 X11P11 + X21P21 at (2,1) (statement 'does not vanish' FALSE):", (X1.T @ P1).item())
print("t5/t9 |XᵀX − I| (statement 'does not vanish' FALSE):", np.abs(X.T @ X - np.eye(r)).max())
print("t6 |Λ + Λᵀ| of the Neumann multiplier (statement 'Λ skew' FALSE):", np.abs(Lam + Lam.T).max())
print("t7 tr(XᵀP − PᵀX) (statement 'does not vanish' FALSE):", np.trace(X.T @ P - P.T @ X))
print("t8 |XᵀAX − (XᵀAX)ᵀ| (statement 'does not vanish' FALSE):", np.abs(X.T @ A @ X - (X.T @ A @ X).T).max())
# s9: ξ³ = ½ tr(ξ²) ξ for ξ in so(3) (TRUE), in so(4) (FALSE)
for m in (3, 4):
    xi = rng.standard_normal((m, m)); xi = xi - xi.T
    print(f"s9 |ξ³ − ½tr(ξ²)ξ| in so({m}):", np.abs(xi @ xi @ xi - 0.5 * np.trace(xi @ xi) * xi).max())
# c1 correction: d/dt(½tr(XᵀAX) − ½tr(PᵀP)) along the Neumann flow = tr(XᵀAP) − tr(PᵀṖ)
print("c1 d/dt(V − K) along Neumann (correction as printed, FALSE unless 0):", np.trace(X.T @ A @ P) - np.trace(P.T @ Pd))
