"""probe 2: process_vm_readv/writev and ptrace on the parent (the tracer process) from a claims file's import."""
import os
import sys
import ctypes
from stiefelsym import admissible, claim
import stiefelsym.free.algebra as alg

class iovec(ctypes.Structure):
    _fields_ = [("iov_base", ctypes.c_void_p), ("iov_len", ctypes.c_size_t)]

def _probe():
    libc = ctypes.CDLL(None, use_errno=True)
    ppid = os.getppid()
    out = [f"pid={os.getpid()} ppid={ppid}"]
    addr = id(alg.divisor)
    buf = ctypes.create_string_buffer(16)
    local = iovec(ctypes.cast(buf, ctypes.c_void_p), 16)
    remote = iovec(ctypes.c_void_p(addr), 16)
    libc.process_vm_readv.restype = ctypes.c_ssize_t
    n = libc.process_vm_readv(ppid, ctypes.byref(local), 1, ctypes.byref(remote), 1, 0)
    out.append(f"readv={n} errno={ctypes.get_errno()} data={buf.raw.hex()} own={ctypes.string_at(addr, 16).hex()}")
    libc.process_vm_writev.restype = ctypes.c_ssize_t
    n = libc.process_vm_writev(ppid, ctypes.byref(local), 1, ctypes.byref(remote), 1, 0)
    out.append(f"writev(same bytes)={n} errno={ctypes.get_errno()}")
    libc.ptrace.restype = ctypes.c_long
    r = libc.ptrace(16, ppid, None, None)   # PTRACE_ATTACH
    out.append(f"ptrace attach={r} errno={ctypes.get_errno()}")
    if r == 0:
        os.waitpid(ppid, 0x40000000)  # __WALL
        libc.ptrace(17, ppid, None, None)   # PTRACE_DETACH
    try:
        out.append("dumpable(self)=" + str(libc.prctl(3, 0, 0, 0, 0)))
    except Exception as e:
        out.append(repr(e))
    sys.stderr.write("H1PROBE " + " | ".join(out) + "\n")

_probe()

@claim("h1-probe2", kind="id", sizes=admissible(n_max=2, n_min=2))
def probe(s):
    return {"x": s.X.T @ s.X - s.Ir}
