from stiefelsym import admissible, claim

@claim("s78-ing", paper="prep", kind="id", sizes=admissible(n_max=3))
def c(s):
    """X Xᵀ P = P."""
    return {"a": s.X.T @ s.X - s.Ir}
