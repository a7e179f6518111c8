"""Probe (no claim is wrong here): open-file-description locks on the descriptors a job inherits from the zygote
(fd 0, /dev/null), and whether /proc/locks shows them to later jobs.  X^T X - I_r (true)."""
import fcntl
import os
import struct
import sys

from stiefelsym import admissible, claim

out = {}
st = os.fstat(0)
out["fd0"] = (os.readlink("/proc/self/fd/0"), st.st_dev, st.st_ino, oct(fcntl.fcntl(0, fcntl.F_GETFL)))
try:
    with open("/proc/locks") as f:
        out["locks_before"] = [ln for ln in f.read().splitlines() if f":{st.st_ino} " in ln]
except OSError as e:
    out["locks_before"] = f"ERR {e.errno}"
F_OFD_SETLK = 37
for kind, name in ((fcntl.F_RDLCK, "rd"), (fcntl.F_WRLCK, "wr")):
    try:
        fcntl.fcntl(0, F_OFD_SETLK, struct.pack("hhqqi", kind, 0, 5, 1, 0) + b"\0" * 4)
        out["ofd_" + name] = "ok"
    except OSError as e:
        out["ofd_" + name] = f"ERR {e.errno}"
try:
    fcntl.flock(0, fcntl.LOCK_SH | fcntl.LOCK_NB)
    out["flock"] = "ok"
except OSError as e:
    out["flock"] = f"ERR {e.errno}"
try:
    with open("/proc/locks") as f:
        out["locks_after"] = [ln for ln in f.read().splitlines() if f":{st.st_ino} " in ln]
        out["locks_all"] = len(f.read())
except OSError as e:
    out["locks_after"] = f"ERR {e.errno}"
try:
    fd = os.open("/proc/self/fd/0", os.O_RDONLY)
    out["reopen"] = "ok"
except OSError as e:
    out["reopen"] = f"ERR {e.errno}"
print("PROBE", repr(out), file=sys.stderr)
SZ = admissible(n_max=3, where=lambda n, r: r < n)


def f(s):
    return {"x": s.X.T @ s.X - s.Ir}


claim("pl-a", kind="id", sizes=SZ)(f)
