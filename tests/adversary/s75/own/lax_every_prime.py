"""The stop's own attempt on the class of the second review's D1: a Lax partner XXᵀ/q whose denominator q is the
product of the first two primes of the search (p₁ = 2⁶¹ − 1, p₂ = 2⁶² − 57), written without a constant divisible
by either.  The sampled system is inconsistent modulo p₁ and modulo p₂ (each divides the denominator of every
solution), so the search may certify only what it can: no formula whose denominators are prime to p₁ and p₂.  A
certificate that said "no formula holds" would be false: A = XXᵀ/q is a partner (`partner_exists` below, proved by
the exact method).  Flow: Ẋ = Φ³X, Ṗ = Φ³P; L = XXᵀ − qΦ³ (as the second review's lax_hidden_prime.py, with q)."""
from fractions import Fraction

from stiefelsym import claim

Q = (2**61 - 1) * (2**62 - 57)


def _F(s):
    Phi = s.P @ s.X.T - s.X @ s.P.T
    return Phi @ Phi @ Phi


def flow_rotate(s):
    """Ẋ = Φ³X, Ṗ = Φ³P."""
    F = _F(s)
    return {"X": F @ s.X, "P": F @ s.P}


def L_two_primes(s):
    """XXᵀ − qΦ³, q = p₁p₂, as XXᵀ − (q + 7)Φ³ + 7Φ³."""
    F = _F(s)
    return s.X @ s.X.T - F * (Q + 7) + F * 7


@claim("s75-own-partner-two-primes", kind="lax", sizes=[(4, 2)])
def partner_exists(s):
    """dL/dt = [XXᵀ/q, L] along Ẋ = Φ³X, Ṗ = Φ³P, for L = XXᵀ − qΦ³, q = (2⁶¹ − 1)(2⁶² − 57)."""
    A = s.X @ s.X.T * Fraction(1, Q)
    L = L_two_primes(s)
    return {"dL/dt - [A, L]": s.d(L_two_primes, flow_rotate(s)) - (A @ L - L @ A)}
