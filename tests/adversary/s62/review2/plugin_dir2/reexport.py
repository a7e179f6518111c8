from _helpers import ALL, claim


@claim("pd2-reexport", kind="id", sizes=ALL)
def f(s):
    """FALSE: X X^T = I_n (claim imported from a helper module next to the file)."""
    return {"XXt": s.X @ s.X.T - s.In}
