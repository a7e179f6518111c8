"""The magnetic (twisted) flow of ω + ε π*ω_mag conserves its own Hamiltonian (ω_ε(X_H, X_H) = 0), for any field
strength F of so(r) and any H: TRUE.  A twin (another function conserved) is FALSE.  And the twisted bracket is
antisymmetric: TRUE."""
from stiefelsym import admissible, claim
from stiefelsym import twisted

SZ = admissible(n_max=3, r_min=2, n_min=3)


def H1(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H2(t):
    return t.tr((t.X.T @ t.A @ t.X + t.Ir).inv()) + t.X[0, 1] * t.P[1, 0]


def G(t):
    return t.tr(t.X.T @ t.A @ t.X)


@claim("s75-tw-energy-true", kind="id", sizes=SZ)
def tw_energy_true(s):
    """dH/dt = 0 along the twisted flow of H (F = η, generic in so(r)), for H1 and H2: TRUE."""
    F = s.eta
    return {"H1": s.d(H1, twisted.flow(s, H1, F)), "H2": s.d(H2, twisted.flow(s, H2, F))}


@claim("s75-tw-energy-false", kind="id", sizes=SZ)
def tw_energy_false(s):
    """d tr(XᵀAX)/dt = 0 along the twisted flow of H1: FALSE."""
    return {"G": s.d(G, twisted.flow(s, H1, s.eta))}


@claim("s75-tw-antisym", kind="id", sizes=SZ)
def tw_antisym(s):
    """{H2, G}_ε + {G, H2}_ε = 0: TRUE."""
    F = s.eta
    return {"w": twisted.bracket(s, H2, G, F) + twisted.bracket(s, G, H2, F)}


@claim("s75-tw-eps-zero-limit", kind="id", sizes=SZ)
def tw_eps_scaled(s):
    """The twisted flow with F = 0 is the Dirac flow: X-parts agree: TRUE."""
    F = s.eta * 0
    return {"X": twisted.flow(s, H1, F)["X"] - s.dirac_flow(H1)["X"],
            "P": twisted.flow(s, H1, F)["P"] - s.dirac_flow(H1)["P"]}
