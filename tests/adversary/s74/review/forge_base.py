"""A true and a false claim for hand-edited results files (forge_fields.py.in)."""
from stiefelsym import admissible, claim, comm


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s74-forge-true", kind="id", sizes=admissible(n_max=3))
def forge_true(s):
    """dΦ/dt = [XXᵀ, A] along the Neumann flow: TRUE."""
    return {"prep": s.d(lambda t: t.Phi, s.dirac_flow(H)) - comm(s.X @ s.X.T, s.A)}


@claim("s74-forge-false", kind="id", sizes=admissible(n_max=3))
def forge_false(s):
    """dΦ/dt = [A, XXᵀ]: FALSE (the sign)."""
    return {"prep": s.d(lambda t: t.Phi, s.dirac_flow(H)) - comm(s.A, s.X @ s.X.T)}
