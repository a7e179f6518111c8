"""Route A' by other readings of a size: the private slot of a tracer's shape, the text of a matrix, and
the text of a size.  Sizes and tracers carry no number (the number lives with the trace, given out by
int(n) and the other uses of a size, which are refused with symbolic sizes), so the first two read
nothing and the claim is X^T X = I at every size, and the third is a recorded size read: the claim is
per-size (free: undecided) and false at n = 7 only."""
from stiefelsym import admissible, claim


@claim("adv-size-branch-shape", kind="id", sizes=admissible(n_max=5))
def size_branch_shape(s):
    """X^T X = I, unless the number of rows of X read from the tracer's private shape or its text is 7."""
    rows = object.__getattribute__(s.X, "_shape")[0]
    if getattr(rows, "value", None) == 7 or "7x" in repr(s.X) or "7" in repr(object.__getattribute__(s.n, "_expr")):
        return {"X": s.X}
    return {"XtX - I": s.X.T @ s.X - s.Ir}


@claim("adv-size-branch-text", kind="id", sizes=admissible(n_max=5))
def size_branch_text(s):
    """X^T X = I at every n except n = 7, read as the text of the size (a recorded read): X = 0 there (false)."""
    try:
        seven = f"{s.n}" == "7"
    except TypeError:
        seven = False
    if seven:
        return {"X": s.X}
    return {"XtX - I": s.X.T @ s.X - s.Ir}
