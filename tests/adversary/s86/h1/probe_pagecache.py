"""Probe (no claim is wrong here): page-cache residency of a large file every process can read, as state shared by
the jobs of one run.  A region of libpython3.11.a is chosen from the run's network-namespace inode (the same in
every job of a run, another in every run); each job counts the pages of the region that are resident (preadv2
RWF_NOWAIT: EAGAIN when not) and reads the next one.  X^T X - I_r (true)."""
import os
import sys

from stiefelsym import admissible, claim

F = "/root/.pyenv/versions/3.11.7/lib/python3.11/config-3.11-x86_64-linux-gnu/libpython3.11.a"
STEP = 1 << 21          # 2 MiB between probe pages (beyond readahead)
SLOTS = 8


def _count():
    try:
        fd = os.open(F, os.O_RDONLY)
        size = os.fstat(fd).st_size
        ino = os.stat("/proc/self/ns/net").st_ino
        base = (ino * 4096 * 7) % (STEP - 4096 * SLOTS)
        base -= base % 4096
        res = []
        for i in range(SLOTS):
            off = i * STEP + base
            if off >= size:
                break
            b = bytearray(1)
            try:
                os.preadv(fd, [b], off, os.RWF_NOWAIT)
                res.append(1)
            except BlockingIOError:
                res.append(0)
        k = sum(res)
        os.pread(fd, 1, k * STEP + base)
        os.posix_fadvise(fd, k * STEP + base, 4096, os.POSIX_FADV_WILLNEED)
        return k, res, base
    except OSError as e:
        return -1, str(e), 0


print("PROBE", _count(), file=sys.stderr)
SZ = admissible(n_max=3, where=lambda n, r: r < n)


def f(s):
    return {"x": s.X.T @ s.X - s.Ir}


claim("pc-a", kind="id", sizes=SZ)(f)
claim("pc-b", kind="id", sizes=SZ)(f)
