"""Cancellation near float64's precision: (u 2^k + 1) - u 2^k = 1, and relative versions."""
from fractions import Fraction

from stiefelsym import admissible, claim

SZ = admissible(n_min=2, n_max=3)


def u(s):
    return s.tr(s.X.T @ s.A @ s.X) + 1


def make(k):
    def f(s):
        return {"r": (u(s) * 2 ** k + 1) - u(s) * 2 ** k}
    f.__doc__ = f"False: (u 2^{k} + 1) - u 2^{k} = 0."
    return f


for _k in (40, 50, 52, 53, 54, 56, 60, 70):
    claim(f"h2f-cancel-{_k}", kind="id", sizes=SZ)(make(_k))


@claim("h2f-cancel-matrix", kind="id", sizes=SZ)
def cancel_matrix(s):
    """False: (X 2^56 + P) - X 2^56 = 0 (it is P)."""
    return {"r": (s.X * 2 ** 56 + s.P) - s.X * 2 ** 56}


@claim("h2f-cancel-frac", kind="id", sizes=SZ)
def cancel_frac(s):
    """False: (u + 2^-60) - u = 0."""
    return {"r": (u(s) + Fraction(1, 2 ** 60)) - u(s)}


@claim("h2f-cancel-frac-scaled", kind="id", sizes=SZ)
def cancel_frac_scaled(s):
    """False: ((u + 2^-60) - u) 2^60 = 0 (it is 1)."""
    return {"r": ((u(s) + Fraction(1, 2 ** 60)) - u(s)) * 2 ** 60}
