"""Probe (stop 85): what a job's child can still reach of the tracing process (pid 1 of the namespace), now that it
is not dumpable: process_vm_readv/writev, /proc/1/{maps,environ,fd,cmdline}, /proc/1/fd/* reopened, kill(1, 0),
and its own siblings (none should be alive)."""
import ctypes
import os
import sys

from stiefelsym import admissible, claim

S = sys.copyright
ADDR = id(S) + sys.getsizeof(S) - len(S) - 1


class _IOV(ctypes.Structure):
    _fields_ = [("base", ctypes.c_void_p), ("len", ctypes.c_size_t)]


libc = ctypes.CDLL(None, use_errno=True)
buf = ctypes.create_string_buffer(1)
loc, rem = _IOV(ctypes.cast(buf, ctypes.c_void_p), 1), _IOV(ADDR, 1)
libc.process_vm_readv.restype = ctypes.c_ssize_t
n = libc.process_vm_readv(os.getppid(), ctypes.byref(loc), 1, ctypes.byref(rem), 1, 0)
res = [f"ppid={os.getppid()} pid={os.getpid()} uid={os.getuid()} vm_readv={n} errno={ctypes.get_errno()}"]
for p in ("maps", "environ", "cmdline", "fd", "status", "mem"):
    try:
        if p == "fd":
            res.append(f"fd={os.listdir('/proc/1/fd')}")
        else:
            with open(f"/proc/1/{p}", "rb") as f:
                res.append(f"{p}=ok:{len(f.read(4096))}")
    except Exception as exc:  # noqa: BLE001
        res.append(f"{p}=ERR {type(exc).__name__} {exc.errno if hasattr(exc, 'errno') else ''}")
try:
    for fd in os.listdir("/proc/1/fd"):
        try:
            k = os.open(f"/proc/1/fd/{fd}", os.O_WRONLY | os.O_NONBLOCK)
            res.append(f"reopen fd {fd} ok")
            os.close(k)
        except Exception as exc:  # noqa: BLE001
            res.append(f"reopen fd {fd} ERR {exc}")
except Exception:  # noqa: BLE001
    pass
print("PROBE2", " | ".join(res), file=sys.stderr)


@claim("pm-probe2", kind="id", sizes=admissible(n_max=2))
def pm_probe2(s):
    return {"x": s.X.T @ s.X - s.Ir}
