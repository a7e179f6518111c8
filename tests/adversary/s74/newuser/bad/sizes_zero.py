from stiefelsym import claim, admissible
@claim("nu-bad-sizes0", kind="id", sizes=admissible(n_max=0))
def f(s):
    """n_max = 0: no sizes at all."""
    return {"z": s.Phi + s.Phi.T}
