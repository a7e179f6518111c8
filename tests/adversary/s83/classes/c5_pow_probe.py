"""Probe (class 5): the degree marker of a power with a huge exponent (t ** N).
pw-zero:  (tr(XᵀX) − tr(I_r)) · t**N, t = tr(PᵀP), N = 2**70: TRUE (0 on V); the bound printed says what the
          markers think its degree is (a bound below N·2 would be an under-estimate)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)


@claim("pw-zero", kind="id", sizes=SZ)
def pw_zero(s):
    t = s.tr(s.P.T @ s.P)
    return {"x": (s.tr(s.X.T @ s.X) - s.tr(s.Ir)) * t ** (2**70)}


@claim("pw-small", kind="id", sizes=SZ)
def pw_small(s):
    t = s.tr(s.P.T @ s.P)
    return {"x": (s.tr(s.X.T @ s.X) - s.tr(s.Ir)) * t ** 5}
