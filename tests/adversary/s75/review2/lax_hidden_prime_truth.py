"""The truth behind flows/lax_hidden_prime.py: along Ẋ = Φ³X, Ṗ = Φ³P, L = XXᵀ − p·Φ³ (p = 2^61 − 1) has the Lax
partner A = XXᵀ/p: dL/dt − [A, L] = 0 (TRUE), which `discover --lax` calls impossible in its space."""
from fractions import Fraction
from stiefelsym import claim

P61 = 2**61 - 1


def _F(s):
    Phi = s.P @ s.X.T - s.X @ s.P.T
    return Phi @ Phi @ Phi


def _L(s):
    F = _F(s)
    return s.X @ s.X.T - F * (P61 + 5) + F * 5


def _flow(s):
    F = _F(s)
    return {"X": F @ s.X, "P": F @ s.P}


@claim("r2-lax-hidden-prime", kind="lax", sizes=[(4, 2), (3, 2)])
def lax_hidden_prime(s):
    """dL/dt = [XXᵀ/p, L] along Ẋ = Φ³X, Ṗ = Φ³P, for L = XXᵀ − pΦ³, p = 2⁶¹ − 1."""
    A = s.X @ s.X.T * Fraction(1, P61)
    L = _L(s)
    return {"dL/dt - [A, L]": s.d(_L, _flow(s)) - (A @ L - L @ A)}
