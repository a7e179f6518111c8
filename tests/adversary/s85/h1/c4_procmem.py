"""Class 4 (state across jobs), through the first phase's tracing process, which is dumpable (stop 84 made only the
second phase's process non-dumpable): every job's child imports the file, and its import adds 1 to a byte of its
parent's memory with process_vm_writev (the parent is pid 1 of the namespace; /proc is read-only but the syscall
is not); the children forked later inherit the count.  sys.copyright's first byte is the counter (the same address
in every child: they are forks of one process).

One function `_by_count`, registered twice:
  pm-first    its jobs see a count < LIMIT: residual X Xᵀ − I_n       (FALSE at r < n)
  pm-second   its jobs see a count >= LIMIT: residual Xᵀ X − I_r      (TRUE)
The file's code is one function; its verdicts contradict each other (s83's I1, through another door).
Stated where r < n, so that XXᵀ − I_n is false at every stated size.
Worked at 61e92f0f (stop 84); closed at 6302d5ba (the tracing process is not dumpable): both ids fail.
"""
import ctypes
import os
import sys

from stiefelsym import admissible, claim

S = sys.copyright
ADDR = id(S) + sys.getsizeof(S) - len(S) - 1
LIMIT = ord("C") + int(os.environ.get("PM_LIMIT", "4"))


class _IOV(ctypes.Structure):
    _fields_ = [("base", ctypes.c_void_p), ("len", ctypes.c_size_t)]


def _bump():
    libc = ctypes.CDLL(None, use_errno=True)
    buf = ctypes.create_string_buffer(bytes([(ord(S[0]) + 1) % 256]), 1)
    local, remote = _IOV(ctypes.cast(buf, ctypes.c_void_p), 1), _IOV(ADDR, 1)
    libc.process_vm_writev.restype = ctypes.c_ssize_t
    return libc.process_vm_writev(os.getppid(), ctypes.byref(local), 1, ctypes.byref(remote), 1, 0)


COUNT = ord(S[0])
_bump()
print("PMCOUNT", COUNT - ord("C"), file=sys.stderr)

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_count(s):
    if COUNT < LIMIT:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("pm-first", kind="id", sizes=SZ)(_by_count)
claim("pm-second", kind="id", sizes=SZ)(_by_count)
