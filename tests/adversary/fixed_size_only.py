"""A claim that needs fixed sizes (it compares n with a number): traced at each size it is needed at."""
from stiefelsym import admissible, claim


@claim("adv-fixed-size-only", kind="id", sizes=admissible(n_max=3), statement="X^T X = I")
def fixed_size_only(s):
    """True: X^T X = I (written with a test on n)."""
    return {"r": s.X.T @ s.X - s.Ir if s.n >= 1 else s.X}
