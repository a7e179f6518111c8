"""Class 4, the second phase (sizes beyond the listed ones): a size's graph depends on the run's other sizes through
the shared network namespace's Ip:OutNoRoutes counter (see c4_netns_snmp.py).  The function reads int(s.n), so it
is traced at each size, each in a job of its own.

  ns-size: at each size, X X^T - I_n = 0 if fewer than K imports ran before this one in the interpreter, else
           X^T X - I_r = 0.  The text of the function says X X^T = I_n (FALSE at r < n) for the first imports.
  Right outcome: the verdict at (4,2) does not depend on whether (4,1) was asked in the same command.
"""
import socket
import sys

from stiefelsym import admissible, claim


def _count():
    try:
        with open("/proc/net/snmp") as f:
            t = f.read().splitlines()
        return int(t[1].split()[t[0].split().index("OutNoRoutes")])
    except (OSError, ValueError):
        return -1


COUNT = _count()
print(f"NCOUNT {COUNT}", file=sys.stderr)
try:
    socket.socket(socket.AF_INET, socket.SOCK_DGRAM).sendto(b"x", ("127.0.0.1", 9))
except OSError:
    pass
K = 4


@claim("ns-size", kind="id", sizes=admissible(n_max=2, where=lambda n, r: r < n))
def _by_size(s):
    int(s.n)
    if COUNT < K:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}
