"""Class 4 through kernel keyrings: each job looks for a key "h4-mark" in its session, user, user-session,
process and thread keyrings, then adds one to each.  A key found = a job ran before it.

One function under two ids:
  key-first   no mark found: residual X Xᵀ − I_n (FALSE at r < n)
  key-second  a mark found:  residual Xᵀ X − I_r (TRUE)
Right verdict for both: fails.
"""
import ctypes
import sys

from stiefelsym import admissible, claim

libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
RINGS = {"@t": -1, "@p": -2, "@s": -3, "@u": -4, "@us": -5}
found, info = False, {}
for name, ring in RINGS.items():
    rid = libc.syscall(250, 0, ring, 0)           # KEYCTL_GET_KEYRING_ID, no create
    hit = libc.syscall(250, 10, ring, b"user", b"h4-mark", 0)      # KEYCTL_SEARCH
    e1 = ctypes.get_errno()
    info[name] = (rid, hit, e1)
    found = found or hit > 0
for name, ring in RINGS.items():
    add = libc.syscall(248, b"user", b"h4-mark", b"1", 1, ring)   # add_key
    e2 = ctypes.get_errno()
    info[name] += (add, e2)
print("KEY", found, info, file=sys.stderr)
FOUND = found

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_key(s):
    if not FOUND:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("key-first", kind="id", sizes=SZ)(_by_key)
claim("key-second", kind="id", sizes=SZ)(_by_key)
