# ruff: noqa
"""SPAWN confinement premise: a process the claims file's interpreter leaves behind (double fork, setsid, its
descriptors closed) outlives the verification and writes with the user's rights afterwards (here only a marker
under /tmp/s66rv, 3 s after the file was imported)."""
import os, time
from stiefelsym import admissible, claim

with open("/tmp/s66rv/daemon_alive.txt", "a") as f:
    f.write(f"file imported in pid {os.getpid()}\n")
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        os.closerange(0, 4096)
        with open("/tmp/s66rv/daemon_alive.txt", "a") as f:
            f.write(f"daemon started, pid {os.getpid()}\n")
        time.sleep(3)
        with open("/tmp/s66rv/daemon_alive.txt", "a") as f:
            f.write(f"written 3 s later by pid {os.getpid()}\n")
    os._exit(0)


@claim("c13d-true", kind="id", sizes=[(3, 2)])
def t(s):
    """true: X^T X = I."""
    return {"x": s.X.T @ s.X - s.Ir}
