"""Probes (not claims of truth): what item reads of engine values (kind ANY) give."""
from stiefelsym import claim

SZ = [(3, 1)]

def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2

@claim("p-flow0", kind="id", sizes=SZ)
def p_flow0(s):
    F = s.dirac_flow(H)
    return {"a": F[0] - F.Xdot}

@claim("p-flow00", kind="id", sizes=SZ)
def p_flow00(s):
    F = s.dirac_flow(H)
    return {"a": F[0][0]}

@claim("p-grad0", kind="id", sizes=SZ)
def p_grad0(s):
    g = s.gradient(H)
    return {"a": g[0] - s.A @ s.X}

@claim("p-gradXX", kind="id", sizes=SZ)
def p_gradXX(s):
    g = s.gradient(H)
    return {"a": g["X"][0]}
