"""A claims file that writes the tracer child's answer itself: at import (in the child) it finds the pipe to
the verifying process, writes a payload it made with the engine's own encoder and leaves with status 0.  The
payload is well formed; what it says is forged: the claim's symbolic graph and its graph at its one listed
size (2,2) are those of XᵀX = I_r (true), its graph at (3,2) (admitted by its forged admits table, not
listed) is that of Xᵀ X = I_r + XᵀAX − XᵀAX∘… i.e. of the false X_11 = 1; and it asks to be reviewed."""
import fcntl
import json
import os
import stat

from stiefelsym import admissible, claim
from stiefelsym.run import userfile as _uf

SIZES = admissible(n_max=3, n_min=2, r_min=2, r_max=2, condition="r = 2")


@claim("adv-s32b-forged", kind="id", sizes=SIZES, statement="X^T X = I_r", equivariance="covariant")
def forged(s):
    """As sent: X^T X = I_r (symbolic, (2,2)); X_11 = 1 at (3,2)."""
    return {"r": s.X.T @ s.X - s.Ir}


def _false(s):
    return {"r": s.X[0, 0] - s.q(1)}


def _pipe_fd():
    best, err = None, os.fstat(2).st_ino
    for fd in range(3, 64):
        try:
            st = os.fstat(fd)
        except OSError:
            continue
        if stat.S_ISFIFO(st.st_mode) and st.st_ino != err and fcntl.fcntl(fd, fcntl.F_GETFL) & os.O_ACCMODE == os.O_WRONLY:
            best = fd     # the newest pipe: the one to the verifying process
    return best


if os.environ.get("STIEFELSYM_S32B_FORGE") != "0":
    fd = _pipe_fd()
    if fd is not None:                      # only in the tracer child (the verifying process has no such pipe)
        d = _uf._claim_data(forged.claim, [])
        d.pop("keys", None)
        d["graphs"] = [[None, _uf._trace_one(forged, "standard", None)],
                       [[2, 2], _uf._trace_one(forged, "standard", (2, 2))],
                       [[3, 2], _uf._trace_one(_false, "standard", (3, 2))]]
        d["sizes"]["list"] = [[2, 2]]
        d["sizes"]["admits"] = [[n, r, (n, r) in ((2, 2), (3, 2))] for n in range(1, 17) for r in range(1, n + 1)]
        d["sizes"]["where"] = True
        d["reviewed"] = True
        data = json.dumps({"claims": [{"claim": d}]}).encode()
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
        os._exit(0)
