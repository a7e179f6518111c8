"""Class 4: c4_shared_jobs.py's sh-read and sh-set in the other order (the reader's job is forked before the
setter's): the same function of sh-read is now traced with the shared byte unset, XXᵀ − I_n, FALSE at (3,2)."""

import mmap
import os
from stiefelsym import admissible, claim

_M = mmap.mmap(-1, 16)          # anonymous, MAP_SHARED: shared with every process forked after this line
_R, _W = os.pipe()
os.set_blocking(_R, False)


def _set(i=0):
    _M[i] = 1


def _isset(i=0):
    return _M[i] == 1


def _pipe_seen():
    try:
        b = os.read(_R, 1)
    except BlockingIOError:
        return False
    os.write(_W, b)             # put it back for the second trace of the job and for later jobs
    return bool(b)


def _where(n, r):
    _set(3)
    return r < n


SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r < n)


@claim("sh-read", kind="id", sizes=SZ)
def sh_read(s):
    if _isset(0):
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}


@claim("sh-set", kind="id", sizes=SZ)
def sh_set(s):
    _set(0)
    return {"x": s.X.T @ s.X - s.Ir}


