"""Class 4 (stop 85, own): a System V shared memory segment made at import under a fixed key counts the jobs (each
job's import increments it).  The interpreter's IPC objects are removed between jobs (userfile._Between), but that
removal read the confinement from the package's sandbox module, which the interpreter never set (it runs the sandbox
module under another name): one function, refuted as shm-first, was proved as shm-second.

shm-first, shm-second: XX^T - I_n (false at r < n) while the count is at most 3, X^TX - I_r (true) after."""
import ctypes
import sys
from stiefelsym import admissible, claim

libc = ctypes.CDLL(None, use_errno=True)
libc.shmat.restype = ctypes.c_void_p
sid = libc.shmget(0x5EED, 4096, 0o1000 | 0o600)     # IPC_CREAT
addr = libc.shmat(sid, None, 0)
COUNT = -1
if addr not in (None, ctypes.c_void_p(-1).value):
    p = ctypes.cast(addr, ctypes.POINTER(ctypes.c_int))
    p[0] += 1
    COUNT = p[0]
print("SHMCOUNT", sid, COUNT, file=sys.stderr)

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_count(s):
    if COUNT <= 3:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("shm-first", kind="id", sizes=SZ)(_by_count)
claim("shm-second", kind="id", sizes=SZ)(_by_count)
