"""s72 review: a resolvent at a moving mu that equals lambda on V (attempts V1-V6): nu = lambda + tr(XᵀX) − r."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=3)


def nu(s):
    return s.lam + s.tr(s.X.T @ s.X) - s.tr(s.Ir)


@claim("s72-v-difference", paper="No", kind="id", section="t", sizes=SIZES)
def v1(s):
    """R(nu) − R(lambda) = 0 (true on V)."""
    return {"d": s.resolvent(nu(s)) - s.resolvent(s.lam)}


@claim("s72-v-product-zero", paper="No", kind="id", section="t", sizes=SIZES)
def v2(s):
    """R(lambda) R(nu) = 0 (false)."""
    return {"p": s.resolvent(s.lam) @ s.resolvent(nu(s))}


@claim("s72-v-product-square", paper="No", kind="id", section="t", sizes=SIZES)
def v3(s):
    """R(lambda) R(nu) = R(lambda)² (true on V)."""
    R = s.resolvent(s.lam)
    return {"p": R @ s.resolvent(nu(s)) - R @ R}


@claim("s72-v-trace-off", paper="No", kind="id", section="t", sizes=SIZES)
def v4(s):
    """tr R(nu) − tr R(lambda) = 1 (false)."""
    return {"t": s.tr(s.resolvent(nu(s))) - s.tr(s.resolvent(s.lam)) - 1}


@claim("s72-v-derivative-lambda", paper="No", kind="id", section="t", sizes=SIZES)
def v5(s):
    """R(lambda) R(nu) = −(d/dlambda) R(lambda)... written as R(lambda)R(nu)·(lambda − nu) = R(nu) − R(lambda) (true: 0 = 0)."""
    R, Rn = s.resolvent(s.lam), s.resolvent(nu(s))
    return {"p": (R @ Rn) * (s.lam - nu(s)) - (Rn - R)}


@claim("s72-v-two-moving", paper="No", kind="id", section="t", sizes=SIZES)
def v6(s):
    """R(nu) R(nu2) = R(nu)² with nu2 = lambda + tr(PᵀX) (equal on T*V: tr XᵀP = 0) (true)."""
    nu2 = s.lam + s.tr(s.P.T @ s.X)
    Rn = s.resolvent(nu(s))
    return {"p": Rn @ s.resolvent(nu2) - Rn @ Rn}


@claim("s72-v-two-moving-false", paper="No", kind="id", section="t", sizes=SIZES)
def v7(s):
    """R(nu) R(nu2) = 0 (false)."""
    nu2 = s.lam + s.tr(s.P.T @ s.X)
    return {"p": s.resolvent(nu(s)) @ s.resolvent(nu2)}
