"""Module-level code of a claims file records the process it runs in (the test compares it with the CLI's) and
what it sees of the run: its parent's command line, its environment (printed to standard error, which the
verifying process shows)."""
import os
import sys

from stiefelsym import admissible, claim

try:
    with open(f"/proc/{os.getppid()}/cmdline", "rb") as fh:
        _PARENT = fh.read().replace(b"\0", b" ").decode(errors="replace")
except OSError:
    _PARENT = ""
print(f"claims-file-pid {os.getpid()} env={','.join(sorted(os.environ))} parent={_PARENT!r}", file=sys.stderr)


@claim("adv-pid-orthonormal", kind="id", sizes=admissible(n_max=3), statement="X^T X = I")
def pid_orthonormal(s):
    """True: X^T X = I."""
    return {"r": s.X.T @ s.X - s.Ir}
