"""Class 4 through the clock against an anchor every job inherits: the status-change time of an inherited pipe
(descriptor 4: made when the interpreter started, never written since) is the interpreter's start, so
CLOCK_REALTIME − that time is how long the interpreter has run.  Each job's import sleeps 1 s, so the elapsed
time counts the jobs before it (the listing, each claim's metadata, each trace), not a straddle of the two traces.

One function `_by_clock` under two ids:
  clk-first   about 2 s elapsed (2 jobs before its trace): residual X Xᵀ − I_n   (FALSE at r < n)
  clk-second  about 4 s elapsed:                           residual Xᵀ X − I_r    (TRUE)
Right verdict for both: fails.  clk-second proved/checked = wrong verdict.
"""
import os
import sys
import time

from stiefelsym import admissible, claim

try:
    ANCHOR = os.fstat(4).st_ctime
except OSError:
    ANCHOR = time.time()
ELAPSED = time.time() - ANCHOR
print("CLK %.3f" % ELAPSED, file=sys.stderr)
time.sleep(1.0)

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_clock(s):
    if ELAPSED < 3.3:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("clk-first", kind="id", sizes=SZ)(_by_clock)
claim("clk-second", kind="id", sizes=SZ)(_by_clock)
