"""Fourth round (AN): a claim that traces with symbolic sizes but writes a size as an int (an identity of size 3
or 2, whose side is a variable until joined): the graph types at the listed sizes only, while the statement
admits every n.  The free method must not prove it for every n, r."""
from stiefelsym import admissible, claim


@claim("adv-s34-int-size-n", paper="t", kind="id", sizes=admissible(n_min=3, n_max=3))
def int_size_n(s):
    """Stated for every n >= 3 (listed at n = 3): Xᵀ I_3 X = I_r, a graph of n = 3 only."""
    return {"x": s.X.T @ s.identity(3) @ s.X - s.identity(s.r)}


@claim("adv-s34-int-size-r", paper="t", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2))
def int_size_r(s):
    """True at r = 2, the only r it is stated for: I_2 Xᵀ X = I_r."""
    return {"x": s.identity(2) @ s.X.T @ s.X - s.identity(s.r)}


@claim("adv-s34-int-size-false", paper="t", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2))
def int_size_false(s):
    """False: I_2 Xᵀ P = 0."""
    return {"x": s.identity(2) @ s.X.T @ s.P}
