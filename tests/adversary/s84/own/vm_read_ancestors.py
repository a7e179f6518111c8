"""Stop 84's own (after h1's W2): a claims file's import reads its ancestors' memory with process_vm_readv.

Every process above the file's own that the engine runs (the tracing process, and without namespaces the verifying
process too) is not dumpable, so a process of the same user can neither read nor write its memory.  The claim's
value says whether any read succeeded: P − P (0, proved) when every read was refused, P (fails) when one worked.
"""
import ctypes
import os

from stiefelsym import admissible, claim


class _IOVec(ctypes.Structure):
    _fields_ = [("base", ctypes.c_void_p), ("len", ctypes.c_size_t)]


def _readable_address(pid: int):
    try:
        with open(f"/proc/{pid}/maps") as f:
            for line in f:
                addr, perms = line.split()[:2]
                if perms.startswith("r"):
                    return int(addr.split("-")[0], 16)
    except OSError:
        return None
    return None


def _ancestors():
    out, pid = [], os.getppid()
    while pid >= 1 and len(out) < 4:
        out.append(pid)
        if pid == 1:        # (the tracing process, in a PID namespace)
            break
        try:
            with open(f"/proc/{pid}/stat") as f:
                pid = int(f.read().rsplit(")", 1)[1].split()[1])
        except OSError:
            break
    return out


def _read_one(pid: int) -> bool:
    addr = _readable_address(pid)
    if addr is None:
        return False
    libc = ctypes.CDLL(None, use_errno=True)
    buf = ctypes.create_string_buffer(8)
    local = _IOVec(ctypes.cast(buf, ctypes.c_void_p), 8)
    remote = _IOVec(addr, 8)
    return libc.process_vm_readv(pid, ctypes.byref(local), 1, ctypes.byref(remote), 1, 0) == 8


READ = [pid for pid in _ancestors() if _read_one(pid)]


@claim("s84-ancestors-unreadable", kind="id", sizes=admissible(n_max=2))
def ancestors_unreadable(s):
    return {"x": s.P if READ else s.P - s.P}
