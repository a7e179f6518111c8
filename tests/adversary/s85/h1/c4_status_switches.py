"""Class 4 (state across jobs) through what the tracing process (pid 1 of the namespace, not dumpable since stop 84)
still shows every child: /proc/1/status and /proc/1/stat are readable.  Its context switches (and its page faults,
CPU time) grow with every job it has forked and waited for, so a job's import can count the jobs before it.

One function `_by_count` registered twice (s83's I1 shape):
  st-first   its jobs see few context switches: residual X Xᵀ − I_n   (FALSE at r < n)
  st-second  its jobs see more: residual Xᵀ X − I_r                   (TRUE)
Simpler still: the job child's own pid in the pid namespace (3, 5, 7, 12, 14, ...) grows with every fork of the
tracing process; MODE picks the counter (LIMIT 9 on pids: st-first's jobs are pids 5, 7; st-second's 12, 14).
"""
import os
import sys

from stiefelsym import admissible, claim


def _switches():
    with open("/proc/1/status") as f:
        for line in f:
            if line.startswith("voluntary_ctxt_switches"):
                return int(line.split()[1])
    return -1


SW = _switches()
print("STCOUNT", os.getpid(), SW, file=sys.stderr)
LIMIT = 9

SZ = admissible(n_max=3, where=lambda n, r: r < n)


MODE = "status"      # pid 1's context switches (see c4_status_count.py)
COUNT = os.getpid() if MODE == "pid" else SW


def _by_count(s):
    if COUNT < LIMIT:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("sw-first", kind="id", sizes=SZ)(_by_count)
claim("sw-second", kind="id", sizes=SZ)(_by_count)
