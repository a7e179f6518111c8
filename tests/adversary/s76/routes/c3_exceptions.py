"""Class 3: exceptions as a side channel (new variants).

* c3-fake-refusal-phase: the claim raises an exception class of its own named TraceRefused (whose name the
  verifying process maps to the engine's TraceRefused) only in the first phase (no descriptor 3), and builds
  XXᵀ = I_n (FALSE at r < n) in a second phase if one were run.  Truth: FALSE.
* c3-fake-memoryerror: raises a class named MemoryError (a builtin the verifier re-creates) on a FALSE claim.
* c3-message-injection: a refusal whose message holds newlines and a forged result line, and a Markdown table
  row (`| ... | proved |`), to forge a verdict in the terminal and in verification.md.  Truth: no graph.
* c3-except-refusal-branch: catches the engine's refusal of `s.X @ s.X` (spaces mismatch, at r < n a true
  refusal; with symbolic sizes too) and returns a FALSE residual in the handler: the refusal is recorded
  first, so error/undecided is expected.
* c3-recursion-depth: builds its residual from the depth at which RecursionError occurs (depth parity picks
  a TRUE or a FALSE residual); the two traces must agree.
"""
import os
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _phase_two():
    try:
        os.fstat(3)
        return True
    except OSError:
        return False


class TraceRefused(Exception):
    pass


class MemoryError_(Exception):
    pass


MemoryError_.__name__ = "MemoryError"


@claim("c3-fake-refusal-phase", paper="t", kind="id", section="0", sizes=SZ)
def fake_refusal(s):
    """XXᵀ = I_n (FALSE at r < n), with a fake refusal in the first phase."""
    if not _phase_two():
        raise TraceRefused("refused: a division by −5 + n may vanish")
    return {"r": s.X @ s.X.T - s.In}


@claim("c3-fake-memoryerror", paper="t", kind="id", section="0", sizes=SZ)
def fake_memory(s):
    """XXᵀ = I_n (FALSE at r < n), raising a class named MemoryError."""
    raise MemoryError_("out of memory (budget 1 MiB)")


@claim("c3-message-injection", paper="t", kind="id", section="0", sizes=SZ)
def injection(s):
    """A refusal message that forges result lines."""
    raise TraceRefused("x\nc3-message-injection (3,2) exact: proved (0.01s, no randomness)\n"
                       "| `c3-message-injection` | t | 0 | id | – | 1 |  | proved |\n\x1b[2K\rproved")


@claim("c3-except-refusal-branch", paper="t", kind="id", section="0", sizes=SZ)
def except_branch(s):
    """catch the refusal of X @ X and return XXᵀ − I_n (FALSE)."""
    try:
        s.X @ s.X
    except Exception:
        return {"r": s.X @ s.X.T - s.In}
    return {"r": s.X.T @ s.X - s.Ir}


def _depth(k=0):
    try:
        return _depth(k + 1)
    except RecursionError:
        return k


@claim("c3-recursion-depth", paper="t", kind="id", section="0", sizes=SZ)
def recursion_depth(s):
    """Depth parity picks XᵀX − I_r (TRUE) or XXᵀ − I_n (FALSE)."""
    d = _depth()
    if d % 2 == 0:
        return {"r": s.X.T @ s.X - s.Ir, "d": s.const(0) * s.const(d % 2)}
    return {"r": s.X @ s.X.T - s.In, "d": s.const(0) * s.const(d % 2)}
