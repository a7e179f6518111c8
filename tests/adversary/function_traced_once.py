"""A false claim proved because a function handed to the scene is traced once per trace, keyed by the
function object: the claim changes what the function computes (a mutable default argument) between
two uses, and the second use silently reuses the first one's ``fn`` node."""
from stiefelsym import admissible, claim


def H(t, k=[1]):  # noqa: B006 (the mutable default is the trick)
    """k·tr(XᵀAX)/2 + tr(PᵀP)/2, k read when H is called."""
    return t.tr(t.X.T @ t.A @ t.X) * k[0] / 2 + t.tr(t.P.T @ t.P) / 2


@claim("adv-function-once", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def two_potentials_one_gradient(s):
    """The gradients of the Neumann Hamiltonian with k = 1 and with k = 2 are equal (false: their
    X-parts differ by AX)."""
    g1 = s.gradient(H)[0]
    H.__defaults__[0][0] = 2
    try:
        g2 = s.gradient(H)[0]
    finally:
        H.__defaults__[0][0] = 1
    return {"dH1/dX - dH2/dX": g1 - g2}
