# ruff: noqa
"""Flows for `discover` with constants that are 0 or undefined modulo its fixed prime 2^61 - 1."""
P61 = 2**61 - 1


def flow_const_p(s):
    """The geodesic flow of the normal metric, scaled by 1/(2^61 - 1) (a time change: same integrals)."""
    X, P = s.X, s.P
    c = s.q(1, P61)
    return {"X": (P - X @ P.T @ X) * c, "P": (X @ P.T @ P - P @ X.T @ X @ P.T @ X) * c * 0}


def flow_sum_p(s):
    """The same flow times 1/(1 + (2^61 - 2)) written as a division by a sum of constants."""
    X, P = s.X, s.P
    d = s.q(1, 1) + s.q(P61 - 1, 1)
    return {"X": (P - X @ P.T @ X) / d, "P": (P - X @ P.T @ X) * 0}


def flow_mul_p(s):
    """Xdot = P times (1 + (2^61 - 2)) = 2^61 - 1: zero modulo the prime, not over Q."""
    X, P = s.X, s.P
    d = s.q(1, 1) + s.q(P61 - 1, 1)
    return {"X": P * d, "P": -(X @ P.T @ P) * d}


def lax_const_p(s):
    """L(λ) = XXᵀ · (2^61 - 1)/(2^61 - 1) written with the constant 1/(2^61 - 1)."""
    return s.X @ s.X.T * s.q(P61, 1) * s.q(1, P61)


def H_const_p(t):
    """½ tr PᵀP · (1 + (2^61 - 2)) / (2^61 - 1)... as a Hamiltonian with the constant 1/(2^61 - 1)."""
    return t.tr(t.P.T @ t.P) * t.q(1, P61)
