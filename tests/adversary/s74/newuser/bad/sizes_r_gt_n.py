from stiefelsym import claim
@claim("nu-bad-sizes", kind="id", sizes=[(2, 3)])
def f(s):
    """r > n in an explicit size list."""
    return {"z": s.Phi + s.Phi.T}
