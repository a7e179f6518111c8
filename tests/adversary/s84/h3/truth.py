# ruff: noqa: E702, E741
"""h3 truth (no stiefelsym): the divisors of h3_div.py / h3_misc.py at each size, exactly (fractions, random lam, c,
kappa, eps), and numpy checks of the E_<r and resolvent statements."""
import random
from fractions import Fraction as F
import numpy as np

rng = random.Random(1)
lam, c, ka, ep = (F(rng.randint(-50, 50), rng.randint(1, 50)) + F(1, 7) for _ in range(4))
DIV = {
    "lamn-lamr": lambda n, r: (lam + n) * (lam - r),
    "nr1": lambda n, r: n - r + 1, "2nr": lambda n, r: 2 * n - r, "quad": lambda n, r: n * n - n * r + r * r,
    "cancel-num": lambda n, r: F(n * n - r * r, n + r),
    "lampole": lambda n, r: 1 / (lam + n) - 1 / (lam + r), "lampole2": lambda n, r: lam / (lam + n) - lam / (lam + r),
    "lamcubic": lambda n, r: 1 / (lam + n) - 1 / (lam + r) + lam,
    "mixsame": lambda n, r: lam * (n - r) + lam * lam * (n - r), "pow60": lambda n, r: F(n + r) ** 60,
    "negpow-nr": lambda n, r: F(n * n - r * r) ** 2, "c": lambda n, r: c + n, "c-nr": lambda n, r: c * (n - r) * (1 + c),
    "kappa-eps": lambda n, r: ka * ep + n - r, "kappa-eps-nr": lambda n, r: ka * ep * (n - r),
    "nested": lambda n, r: 1 / (F(1, n) + F(1, r)), "nested-nr(1/n-1/(n+r))": lambda n, r: F(1, n) - F(1, n + r),
    "trq": lambda n, r: F(n, 2) + F(r, 3), "rminus1-lam": lambda n, r: (r - 1) * lam + (r - 1),
    "zero-rat-lam": lambda n, r: 1 / (lam + n) - 1 / (lam + n + 1) - 1 / ((lam + n) * (lam + n + 1)),
}
sizes = [(n, r) for n in range(1, 6) for r in range(1, n + 1)]
for name, f in DIV.items():
    zeros = [(n, r) for n, r in sizes if f(n, r) == 0]
    print(f"divisor {name:24s} zero at {zeros if zeros else 'no size n<=5'}")

# E_<r: the first r-1 columns of I_r
for n, r in sizes:
    L = np.eye(r)[:, : r - 1]
    G = L.T @ L
    E = np.eye(r)[:, r - 1:]
    ok = np.allclose(G - G @ G, 0) and np.allclose(L @ L.T + E @ E.T, np.eye(r))
    assert ok
print("E_<r: G - G^2 = 0 and L L^T + E E^T = I_r at every size n <= 5; G has", "(r-1)^2 entries: 0 at r = 1 (vacuous)")
# resolvent identity R(mu1) - R(mu2) = (mu2 - mu1) R(mu1) R(mu2), random symmetric A, mu1 = lam + n, mu2 = lam + r
nr = np.random.default_rng(0)
for n in range(1, 5):
    for r in range(1, n + 1):
        A = nr.standard_normal((n, n)); A = A + A.T
        l = 0.37
        R = lambda m: np.linalg.inv(m * np.eye(n) - A)
        R1, R2 = R(l + n), R(l + r)
        assert np.allclose(R1 - R2 - (r - n) * R1 @ R2, 0)
print("resolvent identity R(lam+n) - R(lam+r) = (r - n) R(lam+n) R(lam+r): holds at every n <= 4 (also r = n)")
