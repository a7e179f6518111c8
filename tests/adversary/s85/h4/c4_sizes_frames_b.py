"""Class 4 across sizes: the second phase's process (`_tracer_by_size`) forks one child per size beyond the
first phase's tables; its frame keeps `status, pid` of the previous size's child, and every job of the next
size is a fork below that frame.  The function reads whether that frame holds a previous child.

sz-hist  (one function, traced per size: it reads int(s.n), so it is refused with symbolic sizes)
  no size traced before it in this phase: residual X Xᵀ − I_n  (FALSE at r < n)
  some size traced before it:             residual Xᵀ X − I_r  (TRUE)
Stated for r < n, every n (listed n <= 2: (2,1)).  Right verdict at every size: fails.  `--size 4,1 --size 4,2`: (4,2) proved = wrong.
"""
import sys

from stiefelsym import admissible, claim


def _before():
    f = sys._getframe()
    while f is not None:
        if f.f_code.co_name == "_tracer_by_size":
            return "pid" in f.f_locals
        f = f.f_back
    return False


BEFORE = _before()
print("SZHIST", BEFORE, file=sys.stderr)


@claim("sz-hist", kind="id", sizes=admissible(n_max=2, where=lambda n, r: r < n))
def sz_hist(s):
    int(s.n)        # a size's number: traced per size
    if BEFORE:
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}
