"""Independent truth (numpy only, no stiefelsym): on the Stiefel variety X^T X = I_r (X n x r via QR),
X^T X - I_r = 0 always (TRUE) and X X^T - I_n != 0 whenever r < n (X X^T is a rank-r projector: FALSE)."""
import numpy as np
rng = np.random.default_rng(0)
for n, r in [(2, 1), (3, 1), (3, 2), (4, 1), (4, 2)]:
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    print(n, r, "|XtX-I|=%.1e" % np.abs(X.T @ X - np.eye(r)).max(), "|XXt-I|=%.3f" % np.abs(X @ X.T - np.eye(n)).max())
