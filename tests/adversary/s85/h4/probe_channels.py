# ruff: noqa: E702
"""Probe (no claim is wrong here): every job prints what it can see of the machine, to find counters that grow
with the jobs before it.  Three claims with the same function; X^T X - I_r (true) in each."""
import ctypes
import gc
import os
import resource
import socket
import sys
import time

from stiefelsym import admissible, claim


def rd(p, n=400):
    try:
        with open(p) as f:
            return f.read(n).replace("\n", " | ")
    except OSError as e:
        return f"ERR {e.errno}"


out = {}
out["pid"] = os.getpid()
fds = {}
for fd in range(0, 12):
    try:
        st = os.fstat(fd)
        fds[fd] = (st.st_ino, int(st.st_ctime_ns % 10**9), st.st_mode)
    except OSError:
        pass
out["fds"] = fds
r, w = os.pipe()
out["newpipe"] = os.fstat(r).st_ino
os.close(r); os.close(w)
s = socket.socket(socket.AF_UNIX)
out["sock_ino"] = os.fstat(s.fileno()).st_ino
try:
    s.bind(b"\0stiefel-h4-probe")
    out["abstract"] = "bound"
except OSError as e:
    out["abstract"] = f"ERR {e.errno}"
# keep the socket open: does the next job see the name?  (it ends with the job)
ps = rd("/proc/stat", 4000)
out["procstat"] = [x for x in ps.split(" | ") if x.startswith(("processes", "ctxt"))]
out["uptime"] = rd("/proc/uptime")
out["loadavg"] = rd("/proc/loadavg")
out["ns"] = {n: os.readlink(f"/proc/self/ns/{n}") for n in sorted(os.listdir("/proc/self/ns"))}
out["self_stat"] = rd("/proc/self/stat").split()[21:23]
out["cg"] = rd("/proc/self/cgroup")
for p in ("/sys/fs/cgroup/pids.current", "/sys/fs/cgroup/cpu.stat", "/sys/fs/cgroup/memory.current"):
    out[p] = rd(p, 200)
libc = ctypes.CDLL(None, use_errno=True)
# keyrings: add a key to the user keyring and count what is there
KEY_SPEC_USER_KEYRING, KEY_SPEC_SESSION = -4, -3
kid = libc.syscall(248, b"user", b"h4probe", b"x", 1, KEY_SPEC_USER_KEYRING)   # add_key
out["add_key"] = (kid, ctypes.get_errno())
out["keys"] = rd("/proc/keys", 2000)
out["key_users"] = rd("/proc/key-users", 500)
out["clocks"] = {c: time.clock_gettime(getattr(time, c)) for c in ("CLOCK_MONOTONIC", "CLOCK_BOOTTIME", "CLOCK_REALTIME")}
out["rus_self"] = resource.getrusage(resource.RUSAGE_SELF)[:4]
out["rus_ch"] = resource.getrusage(resource.RUSAGE_CHILDREN)[:4]
out["env"] = dict(os.environ)
out["atime"] = os.stat(__file__).st_atime_ns
out["uf_status"] = len(getattr(sys.modules.get("stiefelsym.run.userfile"), "_STATUS", {}))
out["gc"] = len(gc.get_objects())
out["sys_inode_pipe"] = rd("/proc/sys/fs/inode-nr")
out["filenr"] = rd("/proc/sys/fs/file-nr")
out["sysvipc"] = rd("/proc/sysvipc/shm")
out["pid_max_ns_last"] = rd("/proc/sys/kernel/ns_last_pid")
out["random_uuid"] = rd("/proc/sys/kernel/random/boot_id")
out["entropy"] = rd("/proc/sys/kernel/random/entropy_avail")
print("PROBE", repr(out), file=sys.stderr)

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def f(s):
    return {"x": s.X.T @ s.X - s.Ir}


for i in range(3):
    claim(f"probe-{i}", kind="id", sizes=SZ)(f)
