"""Energy conservation of H along its own Dirac flow: every mutant of H that changes both uses alike is true."""
from stiefelsym import claim


def H(t):
    c = t.scalar("c")
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.resolvent(c) @ t.X) + t.tr(K @ K @ K.T) / 3


@claim("s76-mut-energy", kind="id", sizes=[(3, 2)])
def energy(s):
    """H is conserved along its own Dirac flow."""
    return {"dH": s.d(H, s.dirac_flow(H))}
