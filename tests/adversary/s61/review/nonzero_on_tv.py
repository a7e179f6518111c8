"""kind="not" claims whose residual vanishes identically on T*V (or the point's own variety): each must
not be `proved` / `numeric` (correct verdict: fails)."""
from stiefelsym import admissible, claim, det
from stiefelsym import systems

SZ = admissible(n_max=4, n_min=2)


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("nz-xtx", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nz_xtx(s):
    """Zero on T*V: XᵀX − I."""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("nz-tangent", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nz_tan(s):
    """Zero on T*V: XᵀP + PᵀX."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("nz-second", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nz_second(s):
    """Zero: YᵀY − I and YᵀQ + QᵀY."""
    return {"r": s.Y.T @ s.Y - s.Ir, "q": s.Y.T @ s.Q + s.Q.T @ s.Y}


@claim("nz-double", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nz_double(s):
    """Zero: XᵀY − I at the double point."""
    z = systems.double_point(s)
    return {"r": z["X"].T @ z["Y"] - s.Ir, "d": z["Xdot"].T @ z["Y"] + z["X"].T @ z["Ydot"]}


@claim("nz-complex", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nz_complex(s):
    """Zero: Z*Z − I at the complex point (realified: Z^T Z)."""
    z = systems.complex_point(s)
    Z, Zd = z["Z"], z["Zdot"]
    return {"r": Z.T @ Z - s.identity(2 * s.r), "d": Zd.T @ Z + Z.T @ Zd}


@claim("nz-flow-tangent", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nz_flow(s):
    """Zero: the Dirac flow is tangent: d/dt(XᵀX) = 0."""
    fl = s.dirac_flow(H)
    return {"r": fl["X"].T @ s.X + s.X.T @ fl["X"]}


@claim("nz-det-sq", paper="t", kind="not", expect="nonzero", section="2",
       sizes=admissible(n_max=3, n_min=2, r_in=("n",)))
def nz_det(s):
    """Zero at r = n: det(X)^2 − 1."""
    return {"r": det(s.X) * det(s.X) - 1}


@claim("nz-metric", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ, realization="metric")
def nz_metric(s):
    """Zero in the metric realization: its constraints."""
    return {"r": s.X.T @ s.X - s.Ir, "q": s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X}
