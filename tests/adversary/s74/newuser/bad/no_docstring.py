from stiefelsym import claim, admissible
@claim("nu-nodoc", kind="id", sizes=admissible(n_max=2))
def f(s):
    return {"z": s.Phi + s.Phi.T}
