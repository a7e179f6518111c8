"""False claims whose refutation comes from an equivariant or diagonal chart (no Cayley chart needed)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("ur2-a-zero", paper="t", kind="id", section="2", sizes=SZ)
def a_zero(s):
    """FALSE: A = 0 (diagonal chart: the claim reads no point)."""
    return {"r": s.A}


@claim("ur2-ptp", paper="t", kind="id", section="2", sizes=SZ)
def ptp(s):
    """FALSE: tr(PᵀP) = 0 (equivariant chart)."""
    return {"r": s.tr(s.P.T @ s.P)}


@claim("ur2-entry", paper="t", kind="id", section="2", sizes=SZ)
def entry(s):
    """FALSE: X[0, 0] = 0 (reads a coordinate: Cayley chart)."""
    return {"r": s.X[0, 0]}
