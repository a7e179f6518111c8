"""Your own claims, verified with `stiefelsym verify --claims examples/my_claims.py`.

Each claim is a function of a scene `s` (one problem size n, r over one field)
that returns named residuals: matrices or scalars that must vanish on T*V_{n,r}.
The engine picks the method, the points and the seed; the docstring goes into
the report.
"""
from stiefelsym import admissible, claim, comm


def H(t):
    """The Neumann Hamiltonian with the Euclidean kinetic energy (kappa = -1/2)."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("my-prep", paper="prep", kind="id", section="5", sizes=admissible(n_max=4),
       statement=r"\frac{d}{dt}\Phi = [XX^T, A]")
def momentum_evolves_by_a_commutator(s):
    """Along the Neumann flow, dΦ/dt = [XXᵀ, A]."""
    flow = s.dirac_flow(H)
    return {"prep": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A)}


@claim("my-psi-conserved", paper="No", kind="id", section="5", sizes=admissible(n_max=4),
       statement=r"\frac{d}{dt}\Psi = 0")
def right_momentum_is_conserved(s):
    """Along the Neumann flow, the right momentum Ψ = XᵀP − PᵀX is conserved."""
    flow = s.dirac_flow(H)
    return {"dPsi/dt": s.d(lambda t: t.Psi, flow)}
