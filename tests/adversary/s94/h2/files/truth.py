"""Truth of the user claims of f1, f2, f5 at random points of T*V(n, r) (numpy), compared with every record."""
import json
import sys
import numpy as np

rng = np.random.default_rng(1)


def point(n, r):
    X = np.linalg.qr(rng.standard_normal((n, n)))[0][:, :r]
    W = rng.standard_normal((r, r)); Om = W - W.T
    P = X @ Om + (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r))
    return X, P


def T(X, P):
    return X.T


TR = {
    ("h2-a-true", None): lambda X, P, n, r: [X.T @ P + P.T @ X],
    ("h2-b-proj", None): lambda X, P, n, r: [(X @ X.T) @ (X @ X.T) - X @ X.T, X.T @ X @ X.T @ P - X.T @ P],
    ("h2-c-xtp-all", None): lambda X, P, n, r: [X.T @ P],
    ("h2-d-xtp-r1", None): lambda X, P, n, r: [X.T @ P],
    ("h2-e-xxt-square", None): lambda X, P, n, r: [X @ X.T - np.eye(n)],
    ("h2-f-xxt-all", None): lambda X, P, n, r: [X @ X.T - np.eye(n)],
    ("h2-g-expect-fails", None): lambda X, P, n, r: [X.T @ X - np.eye(r)],
    ("h2-i-corr", None): lambda X, P, n, r: [X.T @ P - P.T @ X],
    ("h2-i-corr", "the sign of P^T X is +"): lambda X, P, n, r: [X.T @ P + P.T @ X],
    ("h2-i-corr", "a wrong correction: X^T P = 0"): lambda X, P, n, r: [X.T @ P],
    ("h2-pr-true", None): lambda X, P, n, r: [r * (X.T @ P + P.T @ X)],
    ("h2-pr-r1", None): lambda X, P, n, r: [X.T @ P],
    ("h2-pr-r2", None): lambda X, P, n, r: [(r - 2) * X.T @ X + X.T @ P + P.T @ X],
    ("h2-pr-r3", None): lambda X, P, n, r: [(r - 3) ** 2 * X.T @ X],
    ("h2-f5-r1n", None): lambda X, P, n, r: [X.T @ P],
    ("h2-f5-r1n-true", None): lambda X, P, n, r: [X.T @ P + P.T @ X, X @ X.T @ X - X],
    ("h2-f5-r2", None): lambda X, P, n, r: [X.T @ P + P.T @ X],
    ("h2-f5-r2-false", None): lambda X, P, n, r: [X.T @ P],
    ("h2-f5-sq", None): lambda X, P, n, r: [P @ X.T + X @ P.T],
    ("h2-f5-sq-gen", None): lambda X, P, n, r: [P @ X.T + X @ P.T],
    ("h2-f5-sq-gen", "projected: XX^T(PX^T + XP^T)XX^T = 0"):
        lambda X, P, n, r: [X @ X.T @ (P @ X.T + X @ P.T) @ X @ X.T],
    ("h2-f5-sq-gen", "a wrong projection: (PX^T + XP^T)XX^T = 0"):
        lambda X, P, n, r: [(P @ X.T + X @ P.T) @ X @ X.T],
}
NONZERO = {("h2-h-nonzero", None): lambda X, P, n, r: [X.T @ X]}


def holds(key, n, r):
    f = TR.get(key)
    if f is None:
        return None
    return all(max(np.abs(m).max() for m in f(*point(n, r), n, r)) < 1e-9 for _ in range(3))


bad = tot = 0
for path in sys.argv[1:]:
    for rec in json.load(open(path))["results"]:
        key = (rec["claim"], rec.get("variant"))
        v = rec["verdict"]
        if key in NONZERO:
            continue
        sizes = [(rec["n"], rec["r"])] if rec.get("n") else [(n, r) for n in range(1, 8) for r in range(1, n + 1)]
        if rec.get("n") is None:
            continue    # free records: checked by hand (their statement's families)
        t = holds(key, *sizes[0])
        if t is None:
            continue
        tot += 1
        ok = (v in ("proved", "checked", "numeric") and t) or (v == "fails" and not t) or v in ("undecided", "inconclusive")
        if not ok:
            bad += 1
            print("WRONG", path, key, sizes[0], v, "truth", t)
print(f"{tot} sized records compared, {bad} wrong")
