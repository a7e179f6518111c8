"""Third round: false statements about the metric realization's Dirac flow (Lambda in closed form, X^T A^-1 X
conserved, a wrong trace of Lambda M): the free method's Lambda letter and its Sylvester relation must prove none."""
from stiefelsym import admissible, claim


def H_A(t):
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


@claim("adv-s33-metric-lambda-closed-form", paper="t", kind="id", section="9", realization="metric",
       sizes=admissible(n_max=3))
def lam_closed(s):
    """False: Lambda = -P^T A^-2 P holds only when X^T A^-1 X = I."""
    flow = s.dirac_flow(H_A)
    Lam = s.X.T @ flow.Pdot
    return {"Lambda": Lam + s.P.T @ s.Ainv @ s.Ainv @ s.P}


@claim("adv-s33-metric-M-conserved", paper="t", kind="id", section="9", realization="metric",
       sizes=admissible(n_max=3))
def m_conserved(s):
    """False: X^T A^-1 X is not conserved along the flow."""
    flow = s.dirac_flow(H_A)
    return {"dM/dt": s.d(lambda t: t.X.T @ t.Ainv @ t.X, flow)}


@claim("adv-s33-metric-trace-lambda", paper="t", kind="id", section="9", realization="metric",
       sizes=admissible(n_max=3))
def tr_lambda(s):
    """False: tr(Lambda M) = -tr(P^T A^-2 P) (the true value has the factor 1/2... times 2: tr(LM)= -tr(PtA-2P))."""
    flow = s.dirac_flow(H_A)
    Lam = s.X.T @ flow.Pdot
    M = s.X.T @ s.Ainv @ s.X
    return {"tr": s.tr(Lam @ M) + 2 * s.tr(s.P.T @ s.Ainv @ s.Ainv @ s.P)}
