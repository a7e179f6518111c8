"""Class 4 through the memory a job inherits from the tracing process (it is a fork of it): the tracer's
frames (_tracer's `parts`: the JSON of the claims traced before; _run_claim's `results`, `i`) and the engine's
module state (userfile._STATUS: one entry per job waited for).

One function `_by_history` under two ids:
  fr-first   nothing traced before it: residual X Xᵀ − I_n   (FALSE at r < n: X Xᵀ has rank r)
  fr-second  one claim traced before: residual Xᵀ X − I_r    (TRUE on the Stiefel variety)
Right verdict for both: fails (at r < n).  fr-second proved/checked = wrong verdict.
MODE picks the channel: "frames" (parts in _tracer's frame), "status" (len(userfile._STATUS)).
"""
import os
import sys

from stiefelsym import admissible, claim

MODE = os.path.basename(__file__).split("_")[-1].split(".")[0]   # c4_frames_<mode>.py


def _count():
    if MODE == "status":
        uf = sys.modules.get("stiefelsym.run.userfile")
        return len(getattr(uf, "_STATUS", {}))
    f = sys._getframe()
    while f is not None:
        if f.f_code.co_name == "_tracer" and "parts" in f.f_locals:
            return len(f.f_locals["parts"])
        f = f.f_back
    return -1


COUNT = _count()
print("HIST", MODE, COUNT, file=sys.stderr)
LIMIT = 1 if MODE == "frames" else int(os.environ.get("LIMIT", "4"))

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_history(s):
    if COUNT < LIMIT:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("fr-first", kind="id", sizes=SZ)(_by_history)
claim("fr-second", kind="id", sizes=SZ)(_by_history)
