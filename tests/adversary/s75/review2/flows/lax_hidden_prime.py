"""For `stiefelsym discover FILE:flow_rotate --lax FILE:L_hidden`: a Lax pair whose partner has the coefficient
1/p, p = 2^61 − 1 (the first prime of the search).

Flow: Ẋ = FX, Ṗ = FP with F = Φ³, Φ = PXᵀ − XPᵀ (a rotation of both by the skew F; F is conserved: Ḟ = [F, F] = 0).
Lax matrix: L = XXᵀ − p·F, written (p + 5)·(−F) + 5·F (no constant divisible by p; L ≡ XXᵀ mod p).
Then dL/dt = d(XXᵀ)/dt = [F, XXᵀ] and [XXᵀ/p, L] = −[XXᵀ, F] = [F, XXᵀ]: A = (1/p)·XXᵀ is a Lax partner, in the
search space (words of degree <= 3).  Modulo p, L ≡ XXᵀ and [F, XXᵀ] need not be a commutator [W, XXᵀ] of a
word of degree <= 3: the sampled system can be inconsistent there."""

P61 = 2**61 - 1


def _F(s):
    Phi = s.P @ s.X.T - s.X @ s.P.T
    return Phi @ Phi @ Phi


def flow_rotate(s):
    """Ẋ = Φ³X, Ṗ = Φ³P."""
    F = _F(s)
    return {"X": F @ s.X, "P": F @ s.P}


def L_hidden(s):
    """XXᵀ − p·Φ³, p = 2⁶¹ − 1, as XXᵀ − (p + 5)Φ³ + 5Φ³."""
    F = _F(s)
    return s.X @ s.X.T - F * (P61 + 5) + F * 5


def L_control(s):
    """XXᵀ − q·Φ³, q = 2⁴⁰ + 1 (control: the partner XXᵀ/q is found)."""
    F = _F(s)
    return s.X @ s.X.T - F * (2**40 + 1)
