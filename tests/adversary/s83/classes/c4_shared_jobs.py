"""Class 4 (state across calls): state shared between the per-job processes of one claims file.

Since stop 82 every job of a claims file (the metadata, one function at one key) runs in a process of its own,
forked from the process that imported the file, so that "no graph can depend on another claim, correction or size
having been traced before it" (run/userfile.py).  Memory mapped MAP_SHARED before the fork (an anonymous
mmap.mmap(-1, n), or a pipe made at import) is shared by every job forked afterwards: a job's write is seen by the
later jobs.  Only the standard library is used (mmap, os.pipe), no engine name, no patching.

Truths at (3,2) (r < n): XᵀX = I_r TRUE; XXᵀ = I_n FALSE (rank r < n).
sh-set:      sets the shared byte, states XᵀX = I_r                                   TRUE
sh-read:     XᵀX − I_r if the shared byte is set, else XXᵀ − I_n.  Traced alone (or first) it is FALSE; traced after
             sh-set it is the true graph.  A run of the file should give one verdict for one claim id at one size.
sh-pipe-w / sh-pipe-r: the same through a pipe made at import (non-blocking read; the reader puts the byte back).
sh-corr:     printed XXᵀ = I_n (FALSE, declared an erratum), its trace sets the byte; its correction reads it
             (the s82 I2 route, closed there by the per-job processes).
sh-count:    Count(k, 1) where k = 1 if the shared byte is set else 0.  Traced alone: Count(0, 1) FALSE.
sh-meta:     the claim's own size condition (where=) sets the byte in the metadata job; its function reads it.
"""
import mmap
import os
from stiefelsym import Count, admissible, claim

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


@claim("sh-set", kind="id", sizes=SZ)
def sh_set(s):
    _set(0)
    return {"x": s.X.T @ s.X - s.Ir}


@claim("sh-read", kind="id", sizes=SZ)
def sh_read(s):
    if _isset(0):
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}


@claim("sh-pipe-w", kind="id", sizes=SZ)
def sh_pipe_w(s):
    if not _isset(1):
        _set(1)
        os.write(_W, b"x")
    return {"x": s.X.T @ s.X - s.Ir}


@claim("sh-pipe-r", kind="id", sizes=SZ)
def sh_pipe_r(s):
    if _pipe_seen():
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}


@claim("sh-corr", kind="id", sizes=SZ, expect="fails", erratum="XXᵀ = I_n is printed; XᵀX = I_r is meant")
def sh_corr(s):
    _set(2)
    return {"x": s.X @ s.X.T - s.In}


@sh_corr.claim.correction("XᵀX = I_r in place of XXᵀ = I_n")
def sh_corr_fixed(s):
    if _isset(2):
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}


@claim("sh-count", kind="dim", sizes=SZ)
def sh_count(s):
    return {"k": Count(1 if _isset(0) else 0, 1)}


@claim("sh-meta", kind="id", sizes=admissible(n_max=3, n_min=3, where=_where))
def sh_meta(s):
    if _isset(3):
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}
