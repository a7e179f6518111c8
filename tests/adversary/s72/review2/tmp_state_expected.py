"""s72 review2 (attempt S9): the channel of W2 on a claim's declared erratum sizes.  rw2-exp-b states X X^T = I_n
(false at r < n, the same graph in every run: symbolic sizes) with `fails_at` true (the failure expected, an erratum)
only where rw2-exp-a, traced at that size in the same second-phase interpreter, left a mark.  At (20,1) (beyond the
first phase's tables, n <= 16) `verify rw2-exp-b` says "fails UNEXPECTED" (exit 1), `verify` of the whole file says
"fails", as expected (exit 0)."""
import os

from stiefelsym import admissible, claim

MARK = "/tmp/rw2-exp-"


@claim("rw2-exp-a", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1))
def exp_a(s):
    """X^T X = I_r (true); traced per size, leaves a mark."""
    n = int(s.n)
    try:
        with open(MARK + str(n), "w") as fh:
            fh.write("x")
    except OSError:
        pass
    return {"id": s.X.T @ s.X - s.identity(s.r, "r")}


@claim("rw2-exp-b", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1),
       fails_at=lambda n, r: os.path.exists(MARK + str(n)), erratum="expected to fail where a was traced")
def exp_b(s):
    """X X^T = I_n (false for r < n)."""
    return {"id": s.X @ s.X.T - s.identity(s.n, "n")}
