"""Divisions by a polynomial in the sizes that vanishes only at a size beyond the default run (n_max = 3)
but within the stated sizes (every n): the residual is undefined there, so no proof for every n, r may
be given (route Q tested sizes n <= 5 of an admissible(n_max=5) claim)."""
from stiefelsym import admissible, claim

ALL = admissible(n_max=3)


@claim("s78-div-n7", paper="prep", kind="id", sizes=ALL)
def div_n7(s):
    """X·((n − 7)/(n − 7)) = X (undefined at n = 7)."""
    c = s.tr(s.In) - 7
    return {"a": s.X * (c / c) - s.X}


@claim("s78-div-n-r-2", paper="prep", kind="id", sizes=ALL)
def div_nr2(s):
    """tr PᵀP·((n − r − 2)²/(n − r − 2)) = tr PᵀP·(n − r − 2) (undefined at n = r + 2)."""
    c = s.tr(s.In) - s.tr(s.Ir) - 2
    t = s.tr(s.P.T @ s.P)
    return {"a": t * (c * c) / c - t * c}


@claim("s78-div-nr6", paper="prep", kind="id", sizes=ALL)
def div_nr6(s):
    """Φ·((nr − 6)/(nr − 6)) = Φ (undefined at (3,2), (6,1))."""
    c = s.tr(s.In) * s.tr(s.Ir) - 6
    return {"a": s.Phi * (c / c) - s.Phi}


@claim("s78-div-n9-inv", paper="prep", kind="id", sizes=ALL)
def div_n9_inv(s):
    """((n − 9)·I_r)⁻¹·(n − 9) = I_r (undefined at n = 9): a matrix inverse of a size-scalar matrix."""
    c = s.tr(s.In) - 9
    return {"a": (s.Ir * c).inv() * c - s.Ir}


@claim("s78-div-lam-n", paper="prep", kind="id", sizes=ALL)
def div_lam_n(s):
    """A resolvent at λ = ... : R(tr(In)·0 + 1)… written as R(μ) with μ = (n − 5)·λ/(n − 5)."""
    c = s.tr(s.In) - 5
    mu = c * s.lam / c
    return {"a": s.resolvent(mu) @ (s.lam * s.In - s.A) - s.In}
