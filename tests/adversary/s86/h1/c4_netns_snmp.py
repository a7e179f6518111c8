"""Class 4 (state across the jobs of one run): the jobs share the interpreter's network namespace, and its
per-namespace IP counters.  Each import sends one UDP datagram to 127.0.0.1 (loopback is down, ENETUNREACH), which
raises Ip:OutNoRoutes in /proc/net/snmp by one; the value read first counts the imports before this one
(listing 0, nr-first's metadata 1, nr-first's function 2, nr-second's metadata 3, nr-second's function 4).

One function, _by_count, under two ids:
  nr-first  -> X X^T - I_n = 0   FALSE at r < n (X X^T is a rank-r projector, |X X^T - I_n| > 0; truth.py)
  nr-second -> the same function; its graph is X^T X - I_r = 0 (true) only because 3 imports ran before it.
Whatever verdict nr-second gets, the text of the file says X X^T = I_n for count < 3, else X^T X = I_r: a verdict
that differs between nr-first and nr-second for one function is the route.  Expected right verdict: both fail
(or error); a `proved`/`checked` for nr-second is the wrong verdict on a function whose first trace says false.
"""
import socket

from stiefelsym import admissible, claim


def _count():
    try:
        with open("/proc/net/snmp") as f:
            t = f.read().splitlines()
        head, vals = t[0].split(), t[1].split()
        return int(vals[head.index("OutNoRoutes")])
    except (OSError, ValueError):
        return -1


COUNT = _count()
try:
    socket.socket(socket.AF_INET, socket.SOCK_DGRAM).sendto(b"x", ("127.0.0.1", 9))
except OSError:
    pass

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_count(s):
    if COUNT < 3:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("nr-first", kind="id", sizes=SZ)(_by_count)
claim("nr-second", kind="id", sizes=SZ)(_by_count)
