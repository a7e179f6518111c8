"""Review s63: an exact integer constant of more than 4300 decimal digits.  Both claims are TRUE identities
(c X - c X = 0, and (c + 1) tr(X^T X) - c r - r = 0 with c = 2^15000), yet every method answers `error` with
Python's own message "Exceeds the limit (4300 digits) for integer string conversion" (the graph's text encoding,
stiefelsym/ir/graph.py _encode -> str(int))."""
from stiefelsym import admissible, claim

S = admissible(n_max=3, n_min=3, r_min=2, r_max=2)
C = 2 ** 15000


@claim("bc-true-cancel", paper="t", kind="id", section="2", sizes=S)
def true_cancel(s):
    """TRUE: c X - c X = 0 with c = 2^15000."""
    return {"r": s.X * C - s.X * C}


@claim("bc-true-trace", paper="t", kind="id", section="2", sizes=admissible(n_max=3))
def true_trace(s):
    """TRUE: (c + 1) tr(X^T X) - (c + 1) tr(I_r) = 0 with c = 2^15000."""
    return {"r": s.tr(s.X.T @ s.X) * (C + 1) - s.tr(s.Ir) * (C + 1)}
