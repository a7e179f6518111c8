"""s72 review2 (attempt S8): as tmp_state_select.py, through a process instead of a file: rw2-dmn-a, traced at a size
in the second phase, leaves a daemon (double fork, setsid) listening on an abstract Unix socket; rw2-dmn-b, traced
later by another child of the same interpreter, is true iff it can connect.  A fresh /tmp per child would not close
this channel; one interpreter (pid and network namespace) per claim and size would."""
import os
import socket
import time

from stiefelsym import admissible, claim

NAME = b"\0rw2-dmn-"


def _daemon(n):
    if os.fork() != 0:
        return
    try:
        os.setsid()
        if os.fork() != 0:
            os._exit(0)
        srv = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        srv.bind(NAME + str(n).encode())
        srv.listen(8)
        t0 = time.time()
        srv.settimeout(1.0)
        while time.time() - t0 < 60:
            try:
                c, _ = srv.accept()
                c.close()
            except OSError:
                pass
    finally:
        os._exit(0)


def _alive(n):
    c = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        c.connect(NAME + str(n).encode())
        return True
    except OSError:
        return False
    finally:
        c.close()


@claim("rw2-dmn-a", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1))
def dmn_a(s):
    """X^T X = I_r (true); leaves a daemon for its size (once)."""
    n = int(s.n)
    if not _alive(n):
        _daemon(n)
        time.sleep(0.3)
    return {"id": s.X.T @ s.X - s.identity(s.r, "r")}


@claim("rw2-dmn-b", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1))
def dmn_b(s):
    """True iff a's daemon for this size answers."""
    if _alive(int(s.n)):
        return {"id": s.X.T @ s.X - s.identity(s.r, "r")}
    return {"id": s.X @ s.X.T - s.identity(s.n, "n")}
