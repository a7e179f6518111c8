# ruff: noqa
from stiefelsym import admissible, claim


@claim("r65-poly-n", paper="r65", kind="id", sizes=admissible(n_max=5, stated_n_max=6),
       statement=r"X = 0")
def poly_n(s):
    """A false statement whose one-term-dropped candidate holds at n <= 4 only."""
    c = s.tr(s.In)
    R = s.X * ((c - 1) * (c - 2) * (c - 3) * (c - 4))
    return {"res": R + s.X}
