"""s72 review2 (attempt S3): a claim refused with symbolic sizes (it reads int(n)), stated for every n >= 3 at r = 1,
traced at sizes beyond its listed ones in the second phase: one interpreter forks one child per size, and the children
share the interpreter's private /tmp.  At n = 8 it states X X^T = I_n (false) unless n = 7 was traced before it in the
same interpreter (a mark in /tmp), then X^T X = I_r (true).  So `--size 8,1` and `--size 7,1 --size 8,1` give the same
claim at the same size two graphs and two verdicts."""
import os

from stiefelsym import admissible, claim

MARK = "/tmp/rw2-beyond-"


@claim("rw2-tmp-beyond", kind="id", paper="No", section="t",
       sizes=admissible(n_min=3, r_max=1))
def tmp_beyond(s):
    """At n = 8: true iff n = 7 was traced first by the same tracing interpreter."""
    n = int(s.n)
    try:
        with open(MARK + str(n), "w") as fh:
            fh.write("x")
    except OSError:
        pass
    if n == 8 and not os.path.exists(MARK + "7"):
        return {"id": s.X @ s.X.T - s.identity(s.n)}
    return {"id": s.X.T @ s.X - s.identity(s.r)}
