"""Class 4 (state across the jobs of one run) through the host's page cache, which no namespace separates.

The run's private /tmp (made when the run starts) gives a run id: its ctime, the same in every job of a run.  It
picks a window of 8 files of Python's own test suite (readable in the confinement, read by nobody).  Each import
probes the window's files in order with preadv2(RWF_NOWAIT): a file not in the page cache answers EAGAIN (and the
kernel starts reading it in); the index of the first such file is the number of imports before this one (the
import before it started reading that file).  Each import sleeps 0.2 s so that the read-in ends first.

One function, _by_cache, under two ids:
  pc-first  -> X X^T - I_n = 0   FALSE at r < n (X X^T is a rank-r projector; truth.py)
  pc-second -> the same function, whose graph is X^T X - I_r = 0 only because 3 imports ran before it.
Right outcome: one verdict for the one function (fails or error); proved/checked for pc-second is the route.
"""
import glob
import os
import sys
import time

from stiefelsym import admissible, claim

D = "/root/.pyenv/versions/3.11.7/lib/python3.11/test"


def _count():
    try:
        files = sorted(f for f in glob.glob(D + "/**/*.py", recursive=True) if os.path.getsize(f) > 8192)
        run = os.stat("/tmp").st_ctime_ns
        start = (run // 1000) % (len(files) - 8)
        for i, f in enumerate(files[start:start + 8]):
            fd = os.open(f, os.O_RDONLY)
            try:
                os.preadv(fd, [bytearray(1)], 0, os.RWF_NOWAIT)
            except BlockingIOError:
                return i, start
            finally:
                os.close(fd)
        return 8, start
    except (OSError, ValueError):
        return -1, -1


COUNT, START = _count()
print(f"PCOUNT {COUNT} {START}", file=sys.stderr)
time.sleep(0.2)
SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_cache(s):
    if COUNT < 3:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("pc-first", kind="id", sizes=SZ)(_by_cache)
claim("pc-second", kind="id", sizes=SZ)(_by_cache)
