"""What is left of route A' once no trace holds a number: the process that traces a claim knows the run's
command (its command line, and the sizes the run asks for in its memory).  The claim states X^T X = I
unless the run asks for n = 7, where it states X = 0 (false): each run rests on one graph, but the run
that proves it for every n and the run at n = 7 trace different graphs."""
from pathlib import Path

from stiefelsym import admissible, claim


def _seven_asked() -> bool:
    try:
        words = Path("/proc/self/cmdline").read_bytes().split(b"\0")
    except OSError:
        return False
    return any(w.startswith(b"7,") for w in words)


@claim("adv-size-by-command", kind="id", sizes=admissible(n_max=5))
def size_by_command(s):
    """X^T X = I, unless the run's command asks for n = 7: X = 0 there (false)."""
    return {"X": s.X} if _seven_asked() else {"XtX - I": s.X.T @ s.X - s.Ir}
