# ruff: noqa: E702
"""Independent numpy truth (no stiefelsym import) for the static claims whose truth depends on the size."""
import numpy as np
rng = np.random.default_rng(89)
def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    Z = rng.standard_normal((n, r)); W = rng.standard_normal((r, r)); W = W - W.T
    P = X @ W + (np.eye(n) - X @ X.T) @ Z          # XᵀP = W skew
    a = rng.standard_normal(n); A = np.diag(a)
    return X, P, A
for n, r in [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)]:
    X, P, A = point(n, r)
    G, H, K3 = (rng.standard_normal((n, n)) for _ in range(3))
    B, C = rng.standard_normal((r, n)), rng.standard_normal((n, r))
    E, F = rng.standard_normal((r, r)), rng.standard_normal((r, r))
    Kk = X.T @ P
    tr = np.trace
    vals = {
        "constraint XᵀP+PᵀX": np.abs(X.T @ P + P.T @ X).max(),
        "h3-rot3": tr(X @ X.T @ A - A @ X @ X.T),
        "h3-xxta (false r<n)": tr(X @ X.T @ A - A),
        "h3-abac (false)": tr(G @ H @ G @ K3 - G @ G @ H @ K3),
        "h3-reflect (false)": tr(G @ H @ K3 - K3 @ H @ G),
        "h3-rect-cancel": tr(C @ B) - tr(B @ C),
        "h3-ek (false r>=2)": tr(E @ Kk),
        "rnd16-f tr(EEKK)": tr(E @ E @ Kk @ Kk),
        "nest15-f tr(PᵀAX) (0 at r=n)": tr(P.T @ A @ X),
        "nest9-f tr(PᵀX)": tr(P.T @ X),
        "rnd8-f tr(KKPᵀX)": tr(Kk @ Kk @ P.T @ X),
        "h3-five": tr(G @ H @ G @ K3 @ H - H @ G @ H @ G @ K3),
    }
    print((n, r), {k: f"{v:.2e}" for k, v in vals.items()})
