"""Probe (not a trick): is a file written by one job's trace visible to a later job (class 4 through the file system)?
probe-w writes /tmp/h1_s83_marker (and under $HOME, cwd) and states XᵀX = I_r (TRUE).
probe-r states XᵀX = I_r (TRUE) if no marker is visible, XXᵀ = I_n (FALSE) if a marker is visible."""
import os
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=3)
_PATHS = ["/tmp/h1_s83_marker", os.path.join(os.getcwd(), "h1_s83_marker"), "/dev/shm/h1_s83_marker"]


def _write():
    for p in _PATHS:
        try:
            with open(p, "w") as f:
                f.write("1")
        except Exception:
            pass


def _seen():
    return [p for p in _PATHS if os.path.exists(p)]


@claim("probe-w", kind="id", sizes=SZ)
def probe_w(s):
    _write()
    return {"x": s.X.T @ s.X - s.Ir}


@claim("probe-r", kind="id", sizes=SZ)
def probe_r(s):
    if _seen():
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


@claim("probe-self", kind="id", sizes=SZ)
def probe_self(s):
    """FALSE (XXᵀ = I_n) if this job's own write is visible to itself, else TRUE."""
    _write()
    if _seen():
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}
