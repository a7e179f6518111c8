"""Truth of the claims of this folder at random points of T*V(n, r) (numpy; derivatives by central differences),
compared with every sized record of the JSON files given (``stiefelsym verify --format json``)."""
import json
import sys

import numpy as np

rng = np.random.default_rng(7)


def point(n, r):
    X = np.linalg.qr(rng.standard_normal((n, n)))[0][:, :r]
    W = rng.standard_normal((r, r))
    P = X @ (W - W.T) + (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r))
    return X, P, np.diag(rng.uniform(1, 3, n)), rng.uniform(5, 7)


def dd(F, X, P, V, W, h=1e-6):
    return (F(X + h * V, P + h * W) - F(X - h * V, P - h * W)) / (2 * h)


def inv(M):
    return np.linalg.inv(M)


def d1(name, X, P, A, lam, n, r):
    V, W = rng.standard_normal((n, r)), rng.standard_normal((n, r))
    Ir, In = np.eye(r), np.eye(n)
    if name == "h2d-inv":
        F = lambda x, p: inv(Ir + x.T @ x + p.T @ p)  # noqa: E731
        M = Ir + X.T @ X + P.T @ P
        dM = V.T @ X + X.T @ V + W.T @ P + P.T @ W
        return dd(F, X, P, V, W) + inv(M) @ dM @ inv(M)
    if name == "h2d-phi-psi":
        F = lambda x, p: (p @ x.T - x @ p.T) @ x - x @ (x.T @ p - p.T @ x)  # noqa: E731
        Phi, Psi = P @ X.T - X @ P.T, X.T @ P - P.T @ X
        dPhi = W @ X.T + P @ V.T - V @ P.T - X @ W.T
        dPsi = V.T @ P + X.T @ W - W.T @ X - P.T @ V
        return dd(F, X, P, V, W) - (dPhi @ X + Phi @ V - V @ Psi - X @ dPsi)
    if name == "h2d-resolvent-moving":
        A = A + 10 * In        # eigenvalues away from mu = tr X^T X = r (a pole spoils the differences)
        F = lambda x, p: inv(np.trace(x.T @ x) * In - A)  # noqa: E731
        R = inv(np.trace(X.T @ X) * In - A)
        return dd(F, X, P, V, 0 * W) + R @ R * 2 * np.trace(V.T @ X)
    if name == "h2d-nested":
        F = lambda x, p: np.trace((x.T @ A @ x) @ (x.T @ A @ x))  # noqa: E731
        h = 1e-4
        second = (F(X + h * V, P) - 2 * F(X, P) + F(X - h * V, P)) / h ** 2
        M, dM, ddM = X.T @ A @ X, V.T @ A @ X + X.T @ A @ V, 2 * V.T @ A @ V
        return np.array([second - (2 * np.trace(dM @ dM) + 2 * np.trace(M @ ddM))]) / max(1, abs(second))
    if name == "h2d-grad-nonsym":
        f = lambda x, p: np.trace((x.T @ A @ p) @ (x.T @ A @ p) @ inv(p.T @ p))  # noqa: E731
        B, C = X.T @ A @ P, inv(P.T @ P)
        K = C @ B @ B @ C
        gX, gP = A @ P @ (B @ C + C @ B), A @ X @ (B @ C + C @ B).T - P @ (K + K.T)
        scale = 1 + np.abs(gX).sum() + np.abs(gP).sum()     # C = (P^T P)^{-1} may be large: a relative test
        return np.array([dd(f, X, P, V, W) - np.sum(gX * V) - np.sum(gP * W)]) / scale
    if name in ("h2d-entry-T", "h2d-entry-T-false"):
        F = lambda x, p: np.array([(x.T @ p).T[0, 1]])  # noqa: E731
        man = (V.T @ P + X.T @ W)[1, 0] if name == "h2d-entry-T" else (V.T @ P + X.T @ W)[0, 1]
        return dd(F, X, P, V, W) - man
    if name == "h2r-d-entry":
        return np.array([2 * (X.T @ A @ X)[0, 1] * A[0, 0]])
    if name == "h2r-grad-entry":
        return np.array([2 * (X.T @ A @ X)[0, 1] * A[0, 0]])     # tr(X^T A X (E01 + E10)) = 2 (X^T A X)_{01}
    if name == "h2r-d-entry-true":
        return np.zeros(1)
    return None


def flow_entry(X, P, A, lam, n, r):
    """d tr(P^T A X)/dt a_1 along the Dirac flow of tr P^T P / 2 + (X^T A X)_{12}: X' = P, P' = -A X S + X Lam."""
    S = np.zeros((r, r))
    S[0, 1] = S[1, 0] = 1
    Lam = (X.T @ A @ X @ S + S @ X.T @ A @ X) / 2 - P.T @ P
    Pd = -A @ X @ S + X @ Lam
    return np.array([(np.trace(Pd.T @ A @ X) + np.trace(P.T @ A @ P)) * A[0, 0]])


def cpoint(n, r):
    """A point Z of the complex W(n, r) (Z^* Z = I) and a tangent vector V (Z^* V + V^* Z = 0), realified."""
    Z = np.linalg.qr(rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n)))[0][:, :r]
    W = rng.standard_normal((r, r)) + 1j * rng.standard_normal((r, r))
    V = Z @ (W - W.conj().T) + (np.eye(n) - Z @ Z.conj().T) @ (rng.standard_normal((n, r)) + 0j)

    def re(M):
        return np.block([[M.real, -M.imag], [M.imag, M.real]])
    return re(Z), re(V)


def cJ(m):
    return np.block([[np.zeros((m, m)), -np.eye(m)], [np.eye(m), np.zeros((m, m))]])


def complex_claims(name, n, r):
    Z, V = cpoint(n, r)
    return {"h2z-unitary": lambda: Z.T @ Z - np.eye(2 * r), "h2z-tangent": lambda: Z.T @ V + V.T @ Z,
            "h2z-tangent-false": lambda: Z.T @ V, "h2z-imag-false": lambda: (Z.T @ V)[r:, :r],
            "h2z-real-false": lambda: Z[n:, :r], "h2z-first-entry-false": lambda: np.array([Z[n, 0]]),
            "h2z-complex-structure": lambda: cJ(n) @ Z - Z @ cJ(r),
            "h2z-projector-false": lambda: Z @ Z.T - np.eye(2 * n),
            "h2z-conj-false": lambda: (np.diag([1.0] * n + [-1.0] * n) @ Z @ np.diag([1.0] * r + [-1.0] * r)).T @ Z
            - np.eye(2 * r)}[name]()


SIMPLE = {
    "h2r-flow-entry": flow_entry,
    "h2c-true": lambda X, P, A, lam, n, r: X.T @ P + P.T @ X,
    "h2c-false": lambda X, P, A, lam, n, r: X.T @ P,
    "h2s-family-str": lambda X, P, A, lam, n, r: X.T @ P,
    "h2s-family-hash": lambda X, P, A, lam, n, r: X.T @ P,
    "h2s-family-type": lambda X, P, A, lam, n, r: X.T @ P + P.T @ X,
    "h2p-recursion": lambda X, P, A, lam, n, r: X.T @ P + P.T @ X,
    "h2p-recursion-left": lambda X, P, A, lam, n, r: X.T @ P,
    "h2p-frame": lambda X, P, A, lam, n, r: X.T @ P,
    "h2p-excepthook": lambda X, P, A, lam, n, r: X.T @ P,
    "h2h-gap": lambda X, P, A, lam, n, r: np.array([A[1, 1] - A[0, 0] - 1e-9]),
    "h2h-large": lambda X, P, A, lam, n, r: np.array([np.trace(P.T @ P)]),
}
for k in (40, 50, 52, 53, 54, 56, 60, 70):
    SIMPLE[f"h2f-cancel-{k}"] = lambda X, P, A, lam, n, r: np.ones(1)
for name in ("h2f-cancel-matrix", "h2f-cancel-frac-scaled", "h2f-pow-small", "h2f-pow-diff", "h2f-neg-pow",
             "h2f-sum-cancel", "h2f-pow-huge", "h2f-cancel-frac", "h2h-near-pole", "h2h-near-pole-res",
             "h2h-near-pole-tr"):
    SIMPLE[name] = lambda X, P, A, lam, n, r: np.ones(1)          # nonzero functions (false statements)
SIMPLE["h2f-cancel-matrix"] = lambda X, P, A, lam, n, r: P


def holds(name, n, r):
    vals = []
    for _ in range(3):
        X, P, A, lam = point(n, r)
        try:
            if name.startswith("h2z-"):
                v = complex_claims(name, n, r)
            else:
                v = SIMPLE[name](X, P, A, lam, n, r) if name in SIMPLE else d1(name, X, P, A, lam, n, r)
        except np.linalg.LinAlgError:
            return None         # not defined at this size (P^T P singular: r = n odd, n = 1)
        if v is None:
            return None
        vals.append(np.max(np.abs(v)) if np.size(v) else 0.0)
    return max(vals) < 1e-5


bad = tot = 0
for path in sys.argv[1:]:
    try:
        recs = json.load(open(path))["results"]
    except (ValueError, OSError):
        continue
    for rec in recs:
        if rec.get("n") is None or rec.get("variant") or rec.get("expect") == "nonzero":
            continue
        t = holds(rec["claim"], rec["n"], rec["r"])
        if t is None:
            continue
        v = rec["verdict"]
        tot += 1
        if (v in ("proved", "checked", "numeric") and not t) or (v == "fails" and t):
            bad += 1
            print("WRONG", path, rec["claim"], rec["n"], rec["r"], rec["method"], v, "truth", t)
print(f"{tot} sized records compared with numpy, {bad} wrong")
