"""False claims decided by the exact method on an equivariant chart (its witness path)."""
from stiefelsym import admissible, claim
from stiefelsym.systems import complex_point, ctranspose

SZ = admissible(n_max=3, n_min=1)


@claim("ur-xxt", paper="t", kind="id", section="2", sizes=SZ)
def ur1(s):
    """FALSE for r < n: X Xᵀ = I_n (TRUE at r = n)."""
    return {"r": s.X @ s.X.T - s.In}


@claim("ur-complex-ztz", paper="t", kind="id", section="A2", sizes=SZ)
def ur2(s):
    """FALSE for n >= 2: Zᵀ Z = I_r (plain transpose; TRUE at n = 1? no: Z = e^{i t}, Z^T Z = e^{2it})."""
    Z = complex_point(s)["Z"]
    return {"r": ctranspose(s, Z) @ Z - s.identity(2 * s.r)}


@claim("ur-complex-tr", paper="t", kind="id", section="A2", sizes=SZ)
def ur3(s):
    """FALSE: tr(Z* A Z) = 0 for the real diagonal A."""
    Z = complex_point(s)["Z"]
    return {"r": (Z.T @ s.realify(s.A, s.A * 0) @ Z).trace()}
