"""Probes: which field strengths built from η, θ the twisted steps accept (all are skew by construction)."""
from stiefelsym import claim, twisted
from _h4common import ANY, H_kappa


def _chk(s, F):
    fl = twisted.flow(s, H_kappa, F=F)
    return {"tangent": s.X.T @ fl.Xdot + fl.Xdot.T @ s.X}


@claim("h4p-F-eta-plus-theta", kind="id", sizes=ANY)
def f1(s):
    """F = η + θ (a sum of two skew letters)."""
    return _chk(s, s.eta + s.theta)


@claim("h4p-F-theta", kind="id", sizes=ANY)
def f2(s):
    """F = θ alone."""
    return _chk(s, s.theta)


@claim("h4p-F-eta-plus-eta", kind="id", sizes=ANY)
def f3(s):
    """F = η + η."""
    return _chk(s, s.eta + s.eta)


@claim("h4p-F-eta-minus-eta", kind="id", sizes=ANY)
def f4(s):
    """F = η − η (zero)."""
    return _chk(s, s.eta - s.eta)


@claim("h4p-F-generic-skew-plus-eta", kind="id", sizes=ANY)
def f5(s):
    """F = G + η with G = s.generic('G', 'r', 'r', 'skew')."""
    return _chk(s, s.generic("G", "r", "r", "skew") + s.eta)


@claim("h4p-F-two-generic-skew", kind="id", sizes=ANY)
def f6(s):
    """F = G + H, two generic skew matrices of the claim's own."""
    return _chk(s, s.generic("G", "r", "r", "skew") + s.generic("H", "r", "r", "skew"))


@claim("h4p-F-3-eta", kind="id", sizes=ANY)
def f7(s):
    """F = 3η."""
    return _chk(s, 3 * s.eta)
