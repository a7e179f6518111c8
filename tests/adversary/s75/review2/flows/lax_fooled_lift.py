"""Flows for `stiefelsym discover FILE:flow_fooled --lax LA2`: (N0_XP2) times x = 1/2 + p₁p₂p₃ (p₁, p₂, p₃ the first
three primes of the lift).  Along x·(N0_XP2) the Lax partner of (LA2)'s 𝓛(λ) = λΦ + XXᵀ − λ²A is x·(Φ − λA);
x ≡ 1/2 modulo p₁p₂ and p₁p₂p₃, so the lift's two successive reconstructions agree on 1/2 (wrong)."""
from fractions import Fraction

_P = (2**61 - 1) * (2**62 - 57) * (2**60 - 93)
X_TRUE = Fraction(1, 2) + _P


def _n0(s, c):
    X, P, A = s.X, s.P, s.A
    return {"X": (P - X @ P.T @ X) * c,
            "P": (-(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X) * c}


def flow_fooled(s):
    """(1/2 + p₁p₂p₃)·(N0_XP2)."""
    return _n0(s, X_TRUE)


def flow_half(s):
    """(1/2)·(N0_XP2) (control)."""
    return _n0(s, Fraction(1, 2))


def flow_p1(s):
    """(2⁶¹ − 1)·(N0_XP2): a constant divisible by the first prime (that prime is skipped); partner p₁(Φ − λA)."""
    return _n0(s, 2**61 - 1)


def flow_p1p2(s):
    """p₁p₂·(N0_XP2): divisible by the first two primes; partner p₁p₂(Φ − λA)."""
    return _n0(s, (2**61 - 1) * (2**62 - 57))


def flow_hidden_p1p2(s):
    """p₁p₂·(N0_XP2) written (p₁p₂ + 3)·N0 − 3·N0: no constant divisible by p₁ or p₂, but the flow is 0 modulo both,
    where every L-commuting word looks like a partner and 0 like the particular one.  Partner: p₁p₂(Φ − λA)."""
    big, small = _n0(s, (2**61 - 1) * (2**62 - 57) + 3), _n0(s, 3)
    return {"X": big["X"] - small["X"], "P": big["P"] - small["P"]}
