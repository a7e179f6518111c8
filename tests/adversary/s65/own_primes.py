# ruff: noqa
"""The stop's own attempt on discover's primes: a constant divisible by every prime the search tries.

Ẋ = cP, Ṗ = −cXPᵀP with c = 1 + (p₁p₂p₃ − 1): 0 modulo each of 2^61 − 1, 2^62 − 57, 2^60 − 93 (discover.PRIMES), so
every monomial looks conserved at each prime; over ℚ only tr(PPᵀ) is (the geodesic flow of the normal metric scaled
by c).  Written as a sum of two constants, so no single constant of the graph is divisible by a prime."""
P = (2**61 - 1) * (2**62 - 57) * (2**60 - 93)


def flow_every_prime(s):
    c = s.q(1, 1) + s.q(P - 1, 1)
    return {"X": s.P * c, "P": -(s.X @ s.P.T @ s.P) * c}


def flow_two_primes(s):
    """0 modulo the first two primes only: the third gives the flow's space."""
    c = s.q(1, 1) + s.q((2**61 - 1) * (2**62 - 57) - 1, 1)
    return {"X": s.P * c, "P": -(s.X @ s.P.T @ s.P) * c}
