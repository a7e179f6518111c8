from stiefelsym import admissible, claim


@claim("pd2-good", kind="id", sizes=admissible(n_max=3))
def good(s):
    """TRUE: X^T X - I = 0."""
    return {"XtX": s.X.T @ s.X - s.Ir}
