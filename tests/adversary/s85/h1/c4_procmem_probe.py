"""Probe: can a job's child write its parent's memory (process_vm_writev; /proc is read-only in the namespaces)?
The first phase's tracing process (pid 1 of the namespace) is not made non-dumpable; the second phase's is."""
import ctypes
import os
import sys

from stiefelsym import admissible, claim

S = sys.copyright
OFF = sys.getsizeof(S) - len(S) - 1
ADDR = id(S) + OFF


class _IOV(ctypes.Structure):
    _fields_ = [("base", ctypes.c_void_p), ("len", ctypes.c_size_t)]


def _vm(write, pid, addr, buf):
    libc = ctypes.CDLL(None, use_errno=True)
    fn = libc.process_vm_writev if write else libc.process_vm_readv
    fn.restype = ctypes.c_ssize_t
    local = _IOV(ctypes.cast(buf, ctypes.c_void_p), len(buf))
    remote = _IOV(addr, len(buf))
    n = fn(pid, ctypes.byref(local), 1, ctypes.byref(remote), 1, 0)
    return n, ctypes.get_errno()


ppid = os.getppid()
buf = ctypes.create_string_buffer(1)
n, e = _vm(False, ppid, ADDR, buf)
before = buf.raw
buf2 = ctypes.create_string_buffer(bytes([(before[0] + 1) % 256]), 1)
m, e2 = _vm(True, ppid, ADDR, buf2)
print("PROBE", os.getpid(), ppid, "read", n, e, before, "write", m, e2, "local", S[:1], file=sys.stderr)


@claim("pm-probe", kind="id", sizes=admissible(n_max=2))
def pm_probe(s):
    return {"x": s.X.T @ s.X - s.Ir}
