"""Attacks on the fix of route A' (sizes carry no number): the number lived with the trace, and Python's
introspection reaches the trace.  Each claim states X^T X = I unless its trace holds the number 7 (beyond
its listed sizes, inside its statement), where it would state X = 0 (false).  Closed: a claim that traces
with symbolic sizes is never traced at a number (its graph with symbolic sizes is its graph at every
size), so neither read finds 7 and both claims are X^T X = I at every size."""
import sys

from stiefelsym import admissible, claim


def _seven_by_the_trace(s):
    """The trace's own function of the numbers, reached through the scene's private slot."""
    from stiefelsym.ir.graph import Size
    t = object.__getattribute__(s, "_t")
    return t._numbers(Size(1, "n", None)) == 7


def _seven_by_frames(s):
    """The local n of the engine's trace(), found in the frames above the claim."""
    f = sys._getframe(1)
    while f is not None:
        if f.f_code.co_name == "trace" and "n" in f.f_locals:
            return f.f_locals["n"] == 7
        f = f.f_back
    return False


@claim("adv-size-by-trace", kind="id", sizes=admissible(n_max=5))
def size_by_trace(s):
    """X^T X = I, unless the trace's private state holds n = 7: X = 0 there (false)."""
    return {"X": s.X} if _seven_by_the_trace(s) else {"XtX - I": s.X.T @ s.X - s.Ir}


@claim("adv-size-by-frames", kind="id", sizes=admissible(n_max=5))
def size_by_frames(s):
    """X^T X = I, unless the engine's frames hold n = 7: X = 0 there (false)."""
    return {"X": s.X} if _seven_by_frames(s) else {"XtX - I": s.X.T @ s.X - s.Ir}
