"""A true claim that fails: the function handed to ``s.d`` changes (a closure cell) between two uses,
and the second derivative reuses the first use's ``fn`` node."""
from stiefelsym import admissible, claim


def H(t):
    """The Neumann Hamiltonian."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def scaled_momentum():
    k = 1

    def F(t):
        return t.Phi * k

    def set_k(v):
        nonlocal k
        k = v
    return F, set_k


@claim("adv-function-once-true", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def derivative_is_linear(s):
    """d(2Φ)/dt = 2 dΦ/dt along the Neumann flow (true)."""
    F, set_k = scaled_momentum()
    flow = s.dirac_flow(H)
    d1 = s.d(F, flow)
    set_k(2)
    d2 = s.d(F, flow)
    return {"d(2 Phi) - 2 d(Phi)": d2 - d1 * 2}
