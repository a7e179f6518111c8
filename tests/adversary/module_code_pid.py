"""Module-level code of a claims file records the process it runs in (the test compares it with the CLI's)."""
import os

from stiefelsym import admissible, claim

_OUT = os.environ.get("STIEFELSYM_TEST_PID_FILE")
if _OUT:
    with open(_OUT, "a") as fh:
        fh.write(f"{os.getpid()}\n")


@claim("adv-pid-orthonormal", kind="id", sizes=admissible(n_max=3), statement="X^T X = I")
def pid_orthonormal(s):
    """True: X^T X = I."""
    return {"r": s.X.T @ s.X - s.Ir}
