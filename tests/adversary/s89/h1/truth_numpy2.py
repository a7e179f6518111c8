"""Independent truth (numpy only) for t_dim.py, t_coords.py, t_poly2/3.py and t_y11/t_const.py."""
import numpy as np
from truth_numpy import point, rng

sizes = [(1, 1), (2, 1), (3, 1), (3, 2), (4, 2), (4, 3), (5, 1), (5, 2), (5, 4), (5, 5), (6, 1), (6, 2), (6, 6)]
rows = {}
for n, r in sizes:
    worst = {}
    for _ in range(3):
        X, P = point(n, r)
        A = np.diag(rng.standard_normal(n))
        Phi = P @ X.T - X @ P.T
        Psi = X.T @ P - P.T @ X
        kil = lambda a, b: -0.5 * np.trace(a @ b)
        M = np.linalg.inv(np.eye(n) - Phi @ Phi)
        N = np.eye(n) - Phi @ Phi
        G = X @ X.T
        rk = np.linalg.matrix_rank(Phi, tol=1e-9)
        k_exact = 2 * r if 2 * r <= n else n - (n % 2)
        v = {
            "rank-phi (=2r)": float(rk != 2 * r),
            "rank-phi-exact": float(rk != k_exact),
            "nonzero-psi (holds iff nonzero)": float(np.max(np.abs(Psi)) < 1e-9),
            "casimir residual": abs(kil(Phi, Phi) - np.trace(P.T @ P) - kil(Psi, Psi) / 2),
            "p00": abs(P[0, 0]) if n > 1 else abs(P[0, 0]),
            "x10": abs(X[1, 0]) if n > 1 else 0.0,
            "xtax00": abs((X.T @ A @ X)[0, 0] - A[0, 0]),
            "a01": abs(A[0, 1]) if n > 1 else 0.0,
            "xxt-entry": abs(G[0, 0] - 1),
            "phi-entry": abs(Phi[1, 2]) if n >= 3 else 0.0,
            "big-cube": np.max(np.abs(M @ M @ M @ N @ N @ N - np.eye(n))),
            "big-cube-twin": np.max(np.abs(M @ M @ M @ N @ N - np.eye(n))),
            "big-commute": np.max(np.abs(M @ M @ Phi @ M - M @ Phi @ M @ M)),
            "big-commute-twin": np.max(np.abs(M @ M @ G @ M - M @ G @ M @ M)),
            "cay-inverse": np.max(np.abs(M @ N - np.eye(n))),
        }
        for k, x in v.items():
            worst[k] = max(worst.get(k, 0.0), x)
    for k, x in worst.items():
        rows.setdefault(k, []).append(f"({n},{r}):{'T' if x < 1e-8 else 'F'}")
for k, v in rows.items():
    print(f"{k:32s}", " ".join(v))
# (1,1): T*V = {x = ±1, p = 0}; the second point Y = ±1 independently of X
print("(1,1): X in {+1,-1}, P = 0, Y in {+1,-1}: Y[0,0]=1 F, X[0,0]=1 F, X[0,0]^2=1 T, X*Y=1 F, P=0 T, Q=0 T")
