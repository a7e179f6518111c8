# ruff: noqa: E702
"""Independent truth (numpy only, no stiefelsym): random points of T*V(n, r) = {XᵀX = I, XᵀP + PᵀX = 0}."""
import numpy as np
rng = np.random.default_rng(1)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    if r == n and rng.random() < 0.5:
        X[:, 0] *= -1
    W = rng.standard_normal((r, r)); K = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ K / 2 + (np.eye(n) - X @ X.T) @ Z
    return X, P


def esym(M, k):
    ev = np.linalg.eigvals(M)
    c = np.poly(ev)  # det(wI - M) = sum (-1)^j e_j w^{m-j}
    return 0.0 if k > len(ev) else ((-1) ** k * c[k]).real


def checks(n, r):
    X, P = point(n, r)
    A = np.diag(rng.standard_normal(n))
    mu, nu = rng.standard_normal(2)
    K = X.T @ P
    Phi = P @ X.T - X @ P.T
    Psi = X.T @ P - P.T @ X
    M = np.eye(n) - Phi @ Phi
    Mi = np.linalg.inv(M)
    R = lambda m: np.linalg.inv(m * np.eye(n) - A)
    N = np.linalg.inv(np.eye(r) + K @ K.T)
    V = X.T @ A @ X
    B = R(mu) @ X @ np.linalg.inv(X.T @ R(mu) @ X)
    G = X @ X.T
    out = {
        "minv-phi-commute": Mi @ Phi - Phi @ Mi,
        "minv-xxt-commute": Mi @ G - G @ Mi,
        "resolvent-square": R(mu) @ (mu * np.eye(n) - A) @ R(mu) - R(mu),
        "resolvent-square-twin": R(mu) @ (mu * np.eye(n) - A) @ R(mu) - R(mu) @ R(mu),
        "resolvent-difference": R(mu) - R(nu) - (nu - mu) * R(mu) @ R(nu),
        "resolvent-difference-twin": R(mu) - R(nu) - (mu - nu) * R(mu) @ R(nu),
        "mixed-denominators": np.concatenate([N @ K - K @ N, (X.T @ X + K @ K.T) @ N - np.eye(r)]),
        "mixed-denominators-twin": N @ V - V @ N,
        "shared-factor-entries": X.T @ B - np.eye(r),
        "shared-factor-entries-twin": B @ X.T - np.eye(n),
        "n-minus-5": (n - 5) * X.T @ X,
        "n-minus-6": (n - 6) * X.T @ X,
        "square-only": X @ X.T - np.eye(n),
        "square-phi": Phi - X @ Psi @ X.T,
        "r1-skew": Psi,
        "e6": np.array([esym(X @ X.T + A, 6)]),
        "e6-r": np.array([esym(X.T @ X + P.T @ P, 6)]),
        "e2-xxt": np.array([esym(G, 2) - r * (r - 1) / 2]),
        "e2-xxt-twin": np.array([esym(G, 2) - r * (r + 1) / 2]),
    }
    return {k: float(np.max(np.abs(v))) for k, v in out.items()}


sizes = [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (3, 3), (4, 1), (4, 2), (4, 3), (4, 4), (5, 1), (5, 2), (5, 4), (5, 5),
         (6, 1), (6, 2), (6, 6)]
res = {}
for n, r in sizes:
    worst = {}
    for _ in range(3):
        for k, v in checks(n, r).items():
            worst[k] = max(worst.get(k, 0), v)
    for k, v in worst.items():
        res.setdefault(k, []).append(f"({n},{r}):{'T' if v < 1e-8 else 'F'}")
for k, v in res.items():
    print(f"{k:28s}", " ".join(v))
