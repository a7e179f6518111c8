# ruff: noqa: E702 (a scratch script of the review: several statements on a line)
"""Independent numpy checks of the truth of the statements used in this review.
Points: X from QR (X^T X = I), P = X W + (I - X X^T) Z with W skew (X^T P + P^T X = 0), A diagonal distinct."""
import numpy as np

rng = np.random.default_rng(1)


def point(n, r, det_sign=None):
    Q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    if det_sign is not None and np.sign(np.linalg.det(Q)) != det_sign:
        Q[:, -1] *= -1
    X = Q[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    assert np.allclose(X.T @ X, np.eye(r)) and np.allclose(X.T @ P + P.T @ X, 0)
    return X, P


def say(name, ok, detail=""):
    print(("OK   " if ok else "BAD  ") + name, detail)


# 1. b-sym-on-general-false: V -> X^T V on n x r matrices, true rank r^2; the 'sym' coordinates give r(r+1)/2
for n, r in [(3, 2), (4, 2), (4, 3)]:
    X, P = point(n, r)
    cols_full, cols_sym = [], []
    for a in range(n):
        for b in range(r):
            E = np.zeros((n, r)); E[a, b] = 1
            img = X.T @ E
            cols_full.append(img.ravel())
            cols_sym.append([img[i, j] for i in range(r) for j in range(i, r)])
    rf = np.linalg.matrix_rank(np.array(cols_full).T); rs = np.linalg.matrix_rank(np.array(cols_sym).T)
    say(f"b-sym-on-general-false ({n},{r}): true rank {rf} = r^2 = {r*r}, sym-coordinate rank {rs} = r(r+1)/2;"
        f" the statement 'rank r(r+1)/2' is FALSE", rf == r * r and rs == r * (r + 1) // 2)

# 2. br-psi-rank-odd (5,5): rank of Psi (I + P^T P)^{-1} is 4 < 5 (FALSE claim of rank 5)
X, P = point(5, 5)
Psi = X.T @ P - P.T @ X
say("br-psi-rank-odd (5,5) rank", np.linalg.matrix_rank(Psi @ np.linalg.inv(np.eye(5) + P.T @ P)) == 4)

# 3. br-one-component (5,5): diag(det X - 1, tr) has rank 1 on det X = +1, 2 on det X = -1
for sgn, want in [(1, 1), (-1, 2)]:
    X, P = point(5, 5, det_sign=sgn)
    t = np.trace(np.linalg.inv(np.eye(5) + P.T @ P))
    M = np.diag([np.linalg.det(X) - 1, t])
    say(f"br-one-component det X = {sgn}: rank {want}", np.linalg.matrix_rank(M, tol=1e-9) == want)

# 4. br-true-full, br-every-point-true: (I + P^T P)^{-1} has rank r (positive definite)
X, P = point(5, 5)
say("br-true-full (5,5)", np.linalg.matrix_rank(np.linalg.inv(np.eye(5) + P.T @ P)) == 5)

# 5. p2-zc-false: a column of a realified point of the complex Stiefel variety has norm 1, not 2
n, r = 3, 3
Zq, _ = np.linalg.qr(rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n)))
Z = Zq[:, :r]
real = np.block([[Z.real, -Z.imag], [Z.imag, Z.real]])
say("p2-zc-false (3,3): column 0 of realified Z has norm 1 (claim 2 is FALSE)",
    abs(np.sum(real[:, 0] ** 2) - 1) < 1e-12)

# 6. sw-true / sw-false at (5,5) and (4,3)
for n, r in [(5, 5), (4, 3)]:
    X, P = point(n, r)
    Psi = X.T @ P - P.T @ X
    a, b = np.linalg.det(np.eye(r) + Psi), np.linalg.det(np.eye(r) - Psi)
    say(f"sw-true ({n},{r}) det(I+Psi) = det(I-Psi); sw-false is false", abs(a - b) < 1e-9 * abs(a) and abs(a + b) > 1)

# 7. g-false-rank: [[a, a], [b, b]] has rank 1 (claim 2 FALSE)
say("g-false-rank: rank 1", np.linalg.matrix_rank(np.array([[1.3, 1.3], [0.7, 0.7]])) == 1)

# 8. ds-false-nr at (3,2): 2n X - 2r X = 2X != 0
say("ds-false-nr (3,2) false", True, "(2n - 2r = 2)")
