from stiefelsym import admissible, claim, comm

@claim("s78-smoke", paper="prep", kind="id", sizes=admissible(n_max=3))
def smoke(s):
    """XᵀX = I."""
    return {"a": s.X.T @ s.X - s.Ir}
