# ruff: noqa
"""Probe: r_in in a user's claims file and the dimension-free method."""
from stiefelsym import admissible, claim


@claim("s65p-rin-1-n", kind="id", sizes=admissible(n_max=4, r_in=(1, "n"), condition="r = 1 or r = n"))
def rin_1_n(s):
    """(I - XX^T) P X^T P = 0 at r = 1 (X^T P = 0) and at r = n (XX^T = I), not in between."""
    return {"(I - XX^T) P X^T P": (s.In - s.X @ s.X.T) @ s.P @ s.X.T @ s.P}


@claim("s65p-rin-n", kind="id", sizes=admissible(n_max=4, r_is_n=True, condition="r = n"))
def r_is_n(s):
    """(I - XX^T) P = 0 at r = n."""
    return {"(I - XX^T) P": (s.In - s.X @ s.X.T) @ s.P}
