"""Claims that a hard case does not reach (they read neither λ nor P), verified under --hard near-pole /
large-momenta: the float run is redone at random points, and its confirmation mod p is the hard-case branch
(which accepts any verdict but fails and error).  Docstrings state the truth."""
from stiefelsym import claim

SZ = [(3, 2)]


@claim("s75-uc-undefined", kind="id", sizes=SZ)
def uc_undefined(s):
    """(X·D)/D = X with D = tr(XᵀX) − r, which is 0 on T*V: UNDEFINED (0/0 at every point)."""
    D = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    return {"w": (s.X * D) / D - s.X}


@claim("s75-uc-absorbed", kind="id", sizes=SZ)
def uc_absorbed(s):
    """(10²⁰XᵀAX + 10⁻³⁰XᵀAX) − 10²⁰XᵀAX = 0: FALSE (float absorbs the small term)."""
    M = s.X.T @ s.A @ s.X
    big = s.q(10**20, 1)
    return {"w": (M * big + M * s.q(1, 10**30)) - M * big}


@claim("s75-uc-undefined-scalar", kind="id", sizes=SZ)
def uc_undefined_scalar(s):
    """D/D − 1 = 0 with D = tr(XᵀX) − r: UNDEFINED."""
    D = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    return {"w": D / D - 1}
