"""Flows for `stiefelsym discover FLOW --lax LA2`: the Neumann flow of the normal metric (N0_XP2), and the same
flow times a constant c.  Along c·(N0_XP2), dL/dt = [c𝓐(λ), L] with 𝓐(λ) = Φ − λA, so a Lax partner of
(LA2)'s 𝓛(λ) exists in the search space for every c (c𝓐(λ)): "no formula holds" is FALSE for every c ≠ 0."""


def _n0(s, c):
    X, P, A = s.X, s.P, s.A
    return {"X": (P - X @ P.T @ X) * c,
            "P": (-(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X) * c}


def flow_c1(s):
    """(N0_XP2)."""
    return _n0(s, 1)


def flow_c3(s):
    """3·(N0_XP2)."""
    return _n0(s, 3)


def flow_big(s):
    """(2⁴⁰ + 1)·(N0_XP2): the coefficient is invertible mod 2⁶¹ − 1 but beyond rational reconstruction there."""
    return _n0(s, 2**40 + 1)


def flow_ratio(s):
    """(2¹⁶ + 1)/(2¹⁶ + 3)... a ratio whose numerator and denominator are each below 2³⁰ (reconstructible)."""
    return _n0(s, __import__("fractions").Fraction(2**16 + 1, 2**16 + 3))


def flow_big_ratio(s):
    """(2³¹ + 1)/(2³¹ + 3)·(N0_XP2): a ratio beyond reconstruction modulo each of the search's primes."""
    return _n0(s, __import__("fractions").Fraction(2**31 + 1, 2**31 + 3))


def flow_none(s):
    """(10¹² + 39)·(N0_XP2): its Lax partner for (LA2) is (10¹² + 39)(Φ − λA), whose coefficient has no rational
    reconstruction modulo 2⁶¹ − 1 (|u|, v < 2³⁰): "no formula holds" would be FALSE."""
    return _n0(s, 10**12 + 39)


def H_big(t):
    """½tr(PᵀP) + ½(10¹² + 39) tr(XᵀAX): the Neumann Hamiltonian with a potential of large weight; H itself is
    conserved by its Dirac flow."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) * (10**12 + 39) / 2
