"""The division probe evaluates a claim modulo three fixed primes (methods.PROBE_PRIMES, public): a divisor
that is a nonzero constant over Q but a multiple of their product P, written as 1 + (P − 1) so that no single
constant is divisible by one of them, looks like a division by zero to the probe.  The claims are true (the
divisor is the nonzero number P); a method that answers `error` for them says the claim is undefined at a size
where it is not."""
from stiefelsym import admissible, claim

_P = (2 ** 61 - 1) * (2 ** 62 - 57) * (2 ** 60 - 93)
_SIZE = admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)")


def _c(s):
    return s.q(1) + s.q(_P - 1)


@claim("adv-s33-probe-matrix", kind="id", sizes=_SIZE, statement="X (c / c) = X, c = P")
def probe_matrix(s):
    """True: c = P is a nonzero number."""
    c = _c(s)
    return {"r": s.X * (c / c) - s.X}


@claim("adv-s33-probe-scalar", kind="id", sizes=_SIZE, statement="(c tr P^T P) / c = tr P^T P, c = P")
def probe_scalar(s):
    """True."""
    c = _c(s)
    t = s.tr(s.P.T @ s.P)
    return {"r": (c * t) / c - t}
