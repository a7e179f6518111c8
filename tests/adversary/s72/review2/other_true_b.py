"""s72 review2 (attempt K1: b always true): two claims refused with symbolic sizes, traced at a size beyond their listed ones in the
second phase.  b states X^T X = I_r (true) when a was traced at that size before it in the same tracing
interpreter (a mark in /tmp), else X X^T = I_n (false at r < n).  `verify --claims F rw2-sel-b --size 7,1` and
`verify --claims F --size 7,1` give b at (7,1) two graphs and two verdicts."""

from stiefelsym import admissible, claim

MARK = "/tmp/rw2-sel-"


@claim("rw2-sel-a", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1))
def sel_a(s):
    """X^T X = I_r (true); leaves a mark for its size."""
    n = int(s.n)
    try:
        with open(MARK + str(n), "w") as fh:
            fh.write("x")
    except OSError:
        pass
    return {"id": s.X.T @ s.X - s.identity(s.r)}


@claim("rw2-sel-b", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1))
def sel_b(s):
    """True iff rw2-sel-a was traced at this size first."""
    n = int(s.n)  # noqa: F841  (the size read as a number: the claim is traced per size)
    if True:
        return {"id": s.X.T @ s.X - s.identity(s.r)}
    return {"id": s.X @ s.X.T - s.identity(s.n)}
