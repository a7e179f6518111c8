"""A claims file that prints forged verdict lines (at import, and while its claim is traced) and, when asked,
leaves its process early (status 0, nothing written) or writes stray bytes to the pipe before the answer.
Its one claim is false (X_11 = 1); nothing it prints may read as a verdict, and no way of leaving may read as
a claims file without claims' errors."""
import os
import stat
import sys

from stiefelsym import admissible, claim

FAKE = "adv-s32b-printed (3,2) exact: proved (0.01s, no randomness)"
print(FAKE)
sys.stdout.flush()
print(FAKE, file=sys.__stdout__)


@claim("adv-s32b-printed", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"))
def printed(s):
    """False: X_11 = 1."""
    print(FAKE)
    return {"r": s.X[0, 0] - s.q(1)}


_MODE = os.environ.get("STIEFELSYM_S32B_CHILD", "")
if _MODE == "exit":
    os._exit(0)
if _MODE == "stray":
    err = os.fstat(2).st_ino
    for fd in range(3, 64):
        try:
            st = os.fstat(fd)
        except OSError:
            continue
        if stat.S_ISFIFO(st.st_mode) and st.st_ino != err:
            try:
                os.write(fd, b'{"claims": []}')
            except OSError:
                pass
