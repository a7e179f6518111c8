# ruff: noqa
"""numpy truth of the statements of this folder.
XᵀX = 2 I_r (the false claim of every pytest route): XᵀX = I_r on V(n, r), so the residual is −I_r ≠ 0.
nr_blocks.py / mut_nr.py: P₂ a generic (n − r) × r block, S symmetric (n − r) × (n − r)."""
import numpy as np

rng = np.random.default_rng(0)
for n, r in ((1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (3, 3), (4, 2), (5, 2)):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    P2 = rng.standard_normal((n - r, r))
    S = rng.standard_normal((n - r, n - r)); S = S + S.T
    eta = rng.standard_normal((r, r)); eta = eta - eta.T
    X0 = np.vstack([np.eye(r), np.zeros((n - r, r))]); P0 = np.vstack([eta, P2])
    print((n, r), "XtX-2I:", np.abs(X.T @ X - 2 * np.eye(r)).max().round(3),
          "P2tP2:", np.abs(P2.T @ P2).max().round(3), "trS:", round(float(np.trace(S)), 3),
          "tangent:", np.abs(X0.T @ P0 + P0.T @ X0).max().round(12),
          "P0tP0-etaTeta:", np.abs(P0.T @ P0 - eta.T @ eta).max().round(3),
          "tr(P2tP2)-tr(P2P2t):", round(float(np.trace(P2.T @ P2) - np.trace(P2 @ P2.T)), 12))
print("dim V(n,r) = nr - r(r+1)/2: at (4,2)", 4 * 2 - 3, "; r2c-dim-false claims", 4 * 2 - 1)
