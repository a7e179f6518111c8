"""s60 review2: a write the seal never sees because it exists only between its checks.  The seal computes the
fingerprint at the start of stiefelsym.ir.seal.verify, called just before each evaluation
(stiefelsym/methods/fixed_size.py, call_claim).  This file installs a profile hook (sys.setprofile /
threading.setprofile; no engine attribute written at import) that, each time verify is CALLED, puts the
public dict entry stiefelsym.free.algebra.DIMENSIONS["n"] back, and each time verify RETURNS sets it to the
value of r.  Every fingerprint is taken on the original engine; every evaluation runs on the changed one.
The dimension-free method proves tr I_n = tr I_r for all n, r."""
import sys
import threading

from stiefelsym import admissible, claim
from stiefelsym.free import algebra

N, R = algebra.DIMENSIONS["n"], algebra.DIMENSIONS["r"]


def _hook(frame, event, arg):
    if frame.f_code.co_name == "verify" and frame.f_code.co_filename.endswith("seal.py"):
        if event == "call":
            algebra.DIMENSIONS["n"] = N          # what the fingerprint reads
        elif event == "return":
            algebra.DIMENSIONS["n"] = R          # what the evaluation reads


sys.setprofile(_hook)
threading.setprofile(_hook)


@claim("s60r2-hook-n-is-r", paper="adv", kind="id", sizes=admissible(n_max=3))
def n_is_r(s):
    """False (for r < n): tr(I_n) = tr(I_r)."""
    return {"tr In - tr Ir": s.tr(s.In) - s.tr(s.Ir)}
