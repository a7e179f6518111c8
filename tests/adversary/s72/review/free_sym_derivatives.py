"""s72 review: derivatives and gradients with generic symmetric / skew letters, free against fixed sizes (attempts D1-D6)."""
from stiefelsym import admissible, claim, comm

SIZES = admissible(n_max=4)


@claim("s72-d-sym-along-skew", paper="No", kind="id", section="t", sizes=SIZES)
def d1(s):
    """d/dt tr(XᵀSX) along X' = KX equals tr(Xᵀ[S, K]X) (true)."""
    S = s.generic("S", "n", "n", "sym")
    K = s.generic("K", "n", "n", "skew")
    v = s.d(lambda t: t.tr(t.X.T @ S @ t.X), {"X": K @ s.X})
    return {"d": v - s.tr(s.X.T @ comm(S, K) @ s.X)}


@claim("s72-d-sym-along-skew-false", paper="No", kind="id", section="t", sizes=SIZES)
def d2(s):
    """... equals tr(Xᵀ[K, S]X) (false)."""
    S = s.generic("S", "n", "n", "sym")
    K = s.generic("K", "n", "n", "skew")
    v = s.d(lambda t: t.tr(t.X.T @ S @ t.X), {"X": K @ s.X})
    return {"d": v - s.tr(s.X.T @ comm(K, S) @ s.X)}


@claim("s72-d-right-skew", paper="No", kind="id", section="t", sizes=SIZES)
def d3(s):
    """d/dt (XᵀX) along X' = Xη_r (η_r generic skew on R^r) is 0 (true)."""
    E = s.generic("E", "r", "r", "skew")
    return {"d": s.d(lambda t: t.X.T @ t.X, {"X": s.X @ E})}


@claim("s72-d-right-sym-false", paper="No", kind="id", section="t", sizes=SIZES)
def d4(s):
    """d/dt (XᵀX) along X' = X S_r (S_r generic symmetric) is 0 (false: 2 S_r)."""
    S = s.generic("Sr", "r", "r", "sym")
    return {"d": s.d(lambda t: t.X.T @ t.X, {"X": s.X @ S})}


@claim("s72-grad-sym", paper="No", kind="id", section="t", sizes=SIZES)
def d5(s):
    """The ambient X-gradient of tr(XᵀSX)/2 is SX (true)."""
    S = s.generic("S", "n", "n", "sym")
    HX, HP = s.gradient(lambda t: t.tr(t.X.T @ S @ t.X) / 2)
    return {"HX - SX": HX - S @ s.X, "HP": HP}


@claim("s72-grad-general-false", paper="No", kind="id", section="t", sizes=SIZES)
def d6(s):
    """The ambient X-gradient of tr(XᵀGX)/2 (G general) is GX (false: (G + Gᵀ)X/2)."""
    G = s.generic("G", "n", "n")
    HX, HP = s.gradient(lambda t: t.tr(t.X.T @ G @ t.X) / 2)
    return {"HX - GX": HX - G @ s.X}
