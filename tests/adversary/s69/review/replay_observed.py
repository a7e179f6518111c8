# ruff: noqa
"""Change 2: the typing replay of a symbolic graph at (n, r) now runs in the tracing thread.  In the claims
file's child, a trace hook installed at import (sys.settrace, this thread) sees the replay's frames and the
numbers they hold; the claim then traces another graph once a replay has been seen.  The verifying process
must give the verdict of the graph the child traced with symbolic sizes (false here), never the later one."""
import sys
from stiefelsym import admissible, claim

SEEN = []


def _hook(frame, event, arg):
    if event == "call" and frame.f_code.co_name == "_typed_at":
        SEEN.append((frame.f_locals.get("n"), frame.f_locals.get("r")))
        sys.settrace(None)      # gone before the engine looks again
    return None


@claim("ro-flip", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="false unless a replay was seen")
def flip(s):
    """XᵀX = 2I (false) until the child has replayed a graph at a size, then XᵀX = I (true)."""
    if not SEEN:
        sys.settrace(_hook)     # installed while traced, in this thread: the replay that follows runs here
    k = 1 if SEEN else 2
    return {"gram": s.X.T @ s.X - k * s.Ir, "seen": 0 * s.X.T @ s.X + 0 * len(SEEN) * s.Ir}
