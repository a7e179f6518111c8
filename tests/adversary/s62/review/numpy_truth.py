# ruff: noqa: F841, E702
"""Independent numpy truth of the fuzz claims: 4 random points of T*V(n, r) (X from QR with both signs of det at
r = n, P = XW + (I − XXᵀ)Z, W skew; A symmetric random, not only diagonal, and diagonal)."""
import json
import sys
import numpy as np

rng = np.random.default_rng(7)


def point(n, r, sgn):
    Q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    if np.sign(np.linalg.det(Q)) != sgn:
        Q[:, 0] *= -1
    X = Q[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    A = np.diag(rng.standard_normal(n))
    assert np.allclose(X.T @ X, np.eye(r)) and np.allclose(X.T @ P + P.T @ X, 0)
    return X, P, A


def ev(w, X, P, A, R):
    M = {"X": X, "Xt": X.T, "P": P, "Pt": P.T, "A": A, "R": R}
    out = M[w[0]]
    for t in w[1:]:
        out = out @ M[t]
    return out


def truth(m, n, r):
    vals = []
    for sgn in (1, -1):
        for _ in range(3):
            X, P, A = point(n, r, sgn)
            R = np.linalg.inv(np.eye(r) + P.T @ P)
            a, b = ev(m["w"], X, P, A, R), ev(m["w2"], X, P, A, R)
            if m["traced"]:
                v = np.trace(a) - m["sign"] * np.trace(b)
                scale = abs(np.trace(a)) + abs(np.trace(b)) + 1
            else:
                i, j = m["entry"]
                v = a[i, j] - m["sign"] * b[i, j]
                scale = abs(a[i, j]) + abs(b[i, j]) + 1
            if m["w3"]:
                c = np.trace(ev(m["w3"], X, P, A, R))
                v, scale = v * c, scale * (abs(c) + 1)
            vals.append(abs(v) / scale)
    return bool(max(vals) < 1e-9)


if __name__ == "__main__":
    seed, n, r = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    meta = json.load(open(f"fuzz_meta_{seed}.json"))
    print(json.dumps({m["id"]: truth(m, n, r) for m in meta}))
