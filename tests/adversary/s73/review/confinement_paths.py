"""What a claims file's interpreter can write and read between jobs, leaked into a graph: each claim's residual is
X^T X - I_r (true) plus 1 when its probe succeeds (then the claim is false and the verdict says so).  A `fails`
is not a wrong verdict here (the graph really is false); it shows that the probe succeeded in the sandbox."""
import os

from stiefelsym import admissible, claim

_PATHS = ["/dev/shm/s73mark", "/tmp/s73mark", "/var/tmp/s73mark", os.path.expanduser("~/s73mark"),
          os.path.join(os.path.dirname(os.path.abspath(__file__)), "s73mark"), "/run/s73mark",
          "/dev/mqueue/s73mark"]


def _writable():
    ok = []
    for p in _PATHS:
        try:
            with open(p, "w") as fh:
                fh.write("x")
            ok.append(p)
        except OSError:
            pass
    return ok


def _seen():
    return [p for p in _PATHS if os.path.exists(p)]


@claim("s73-conf-write", kind="id", sizes=admissible(n_max=2))
def conf_write(s):
    """X^T X = I_r, plus 1 for each path the tracing interpreter could write: TRUE iff nothing was written."""
    w = _writable()
    if w:
        print("s73 writable:", w)
    return {"id": s.X.T @ s.X - s.Ir + s.q(len(w)) * s.Ir}


@claim("s73-conf-seen", kind="id", sizes=admissible(n_max=2))
def conf_seen(s):
    """X^T X = I_r, plus 1 for each mark left by an earlier job: TRUE iff no mark is seen."""
    w = _seen()
    if w:
        print("s73 seen:", w)
    return {"id": s.X.T @ s.X - s.Ir + s.q(len(w)) * s.Ir}
