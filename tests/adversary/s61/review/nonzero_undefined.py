"""kind="not" claims whose residual is undefined (a division by something identically 0 on T*V)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4, n_min=2)


@claim("nu-inf", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nu_inf(s):
    """1/(tr XᵀX − r): undefined everywhere."""
    z = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    return {"r": 1 / z}


@claim("nu-nan", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nu_nan(s):
    """(XᵀP + PᵀX)/(tr XᵀX − r): 0/0 everywhere."""
    z = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    return {"r": (s.X.T @ s.P + s.P.T @ s.X) / z}


@claim("nu-pow", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nu_pow(s):
    """(tr(XᵀP))^-1: tr XᵀP = 0 on T*V."""
    return {"r": s.tr(s.X.T @ s.P) ** -1}


@claim("nu-inv", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nu_inv(s):
    """(XᵀP + PᵀX + I)⁻¹ − I = 0 on T*V: zero, not nonzero."""
    return {"r": (s.X.T @ s.P + s.P.T @ s.X + s.Ir).inv() - s.Ir}


@claim("nu-inv-sing", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nu_inv_sing(s):
    """(XᵀP + PᵀX)⁻¹: singular everywhere."""
    return {"r": (s.X.T @ s.P + s.P.T @ s.X).inv()}


@claim("nu-resolvent-pole", paper="t", kind="not", expect="nonzero", section="2", sizes=SZ)
def nu_res(s):
    """R(a_1) = (a_1 I − A)⁻¹: A diagonal, a pole."""
    return {"r": s.resolvent(s.a[0])}
