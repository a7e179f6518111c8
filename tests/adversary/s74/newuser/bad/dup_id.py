from stiefelsym import claim, admissible
@claim("nu-dup", kind="id", sizes=admissible(n_max=2))
def f(s):
    """one"""
    return {"z": s.Phi + s.Phi.T}
@claim("nu-dup", kind="id", sizes=admissible(n_max=2))
def g(s):
    """two"""
    return {"z": s.Psi + s.Psi.T}
