"""Class 4 (state across the jobs of one run): every job inherits descriptor 0 (/dev/null) from the zygote, one open
file description the zygote keeps open.  An open-file-description lock (F_OFD_SETLK, F_RDLCK on a read-only
descriptor) placed on it by a job outlives the job, and /proc/locks shows it to every later job (OFD locks are
listed with pid -1, whatever the PID namespace).  Each import reads how many bytes of /dev/null's inode are
locked (the jobs before it) and locks the next byte.

One function, _by_locks, under two ids:
  ol-first  -> X X^T - I_n = 0   FALSE at r < n (X X^T is a rank-r projector; truth.py)
  ol-second -> the same function, whose graph is X^T X - I_r = 0 only because 3 imports ran before it.
Right outcome: the one function gets one verdict (fails, or error); proved/checked for ol-second is the route.
"""
import fcntl
import os
import struct

from stiefelsym import admissible, claim


def _count():
    try:
        st = os.fstat(0)
        tag = f":{st.st_ino} "
        ends = []
        with open("/proc/locks") as f:
            for ln in f.read().splitlines():
                if "OFDLCK" in ln and tag in ln and f"{os.major(st.st_dev):02x}:{os.minor(st.st_dev):02x}:" in ln:
                    ends.append(int(ln.split()[-1]))
        count = max(ends) + 1 if ends else 0
        fcntl.fcntl(0, 37, struct.pack("hhqqi", fcntl.F_RDLCK, 0, count, 1, 0) + b"\0" * 4)   # F_OFD_SETLK
        return count
    except (OSError, ValueError):
        return -1


COUNT = _count()
SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_locks(s):
    if COUNT < 3:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("ol-first", kind="id", sizes=SZ)(_by_locks)
claim("ol-second", kind="id", sizes=SZ)(_by_locks)
