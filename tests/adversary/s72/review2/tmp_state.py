"""s72 review2 (attempts S1, S2): state across the tracing processes through the tracing interpreter's private /tmp.

S1 `rw2-tmp-size`: a claim refused with symbolic sizes (it reads int(n)), so it is traced at each size in the second
phase, one forked child per size.  Traced at n = 3 it leaves a mark in /tmp; traced at n = 4 it states X X^T = I_n
(false at r < n) unless a mark of n = 3 is there, then X^T X = I_r (true).  The documented property: "what a function
traced at a size sees depends on the file and that size only, not on the run's other sizes nor their number".

S2 `rw2-tmp-a` / `rw2-tmp-b`: each claim is traced in a child of its own "so no claim's graph depends on another
having been traced first"; b reads a mark a leaves."""
import os

from stiefelsym import admissible, claim

MARK = "/tmp/rw2-mark-"


def _mark(name):
    try:
        with open(MARK + name, "w") as fh:
            fh.write("x")
    except OSError:
        pass


@claim("rw2-tmp-size", kind="id", paper="No", section="t", sizes=admissible(n_min=3, n_max=4, r_max=1))
def tmp_size(s):
    """At n = 4: X^T X = I_r if (3,1) was traced first in this interpreter, else X X^T = I_n."""
    n = int(s.n)
    _mark(f"size{n}")
    if n == 4 and not os.path.exists(MARK + "size3"):
        return {"id": s.X @ s.X.T - s.identity(s.n)}
    return {"id": s.X.T @ s.X - s.identity(s.r)}


@claim("rw2-tmp-a", kind="id", paper="No", section="t", sizes=admissible(n_max=3))
def tmp_a(s):
    """X^T X = I_r (true); leaves a mark."""
    _mark("a")
    return {"id": s.X.T @ s.X - s.identity(s.r)}


@claim("rw2-tmp-b", kind="id", paper="No", section="t", sizes=admissible(n_max=3))
def tmp_b(s):
    """X^T X = I_r if a's mark is there (true), else X X^T = I_n (false at r < n)."""
    if os.path.exists(MARK + "a"):
        return {"id": s.X.T @ s.X - s.identity(s.r)}
    return {"id": s.X @ s.X.T - s.identity(s.n)}
