"""A matrix divided by a scalar made of sizes only, under the dimension-free method: which forms run.
All residuals are 0 where defined; each is stated where its divisor is nonzero (n >= 6)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=7, n_min=6, condition="n >= 6")


@claim("s75-fsd-n-minus-5", kind="id", sizes=SZ)
def fsd_a(s):
    """(c X)/c = X, c = n − 5: TRUE for n >= 6."""
    c = s.tr(s.In) - 5
    return {"w": (s.X * c) / c - s.X}


@claim("s75-fsd-scalar-first", kind="id", sizes=SZ)
def fsd_b(s):
    """(c X)/c = X, c = n − r − 5 + r: TRUE for n >= 6."""
    c = s.tr(s.In) - s.tr(s.Ir) - 5 + s.tr(s.Ir)
    return {"w": (s.X * c) / c - s.X}


@claim("s75-fsd-scalar-only", kind="id", sizes=SZ)
def fsd_c(s):
    """(c·tr PᵀP)/c = tr PᵀP, c = n − 5: TRUE for n >= 6."""
    c = s.tr(s.In) - 5
    K = s.tr(s.P.T @ s.P)
    return {"w": (c * K) / c - K}
