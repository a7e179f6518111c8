"""s60 review: public data of verdict modules is not in the seal's fingerprint (stiefelsym.ir.seal._fingerprint
watches code, classes, modules, scalar constants and five registries only).  Loaded in-process
(`load_claims_file`), this file writes one entry of the public dict `stiefelsym.free.algebra.DIMENSIONS`
(no underscore name, no function replaced): the dimension-free method then proves tr(I_n) = tr(I_r).
Through the CLI or `stiefelsym.load` the file runs in the sandbox only (correct verdicts)."""
from stiefelsym import admissible, claim
from stiefelsym.free import algebra

algebra.DIMENSIONS["n"] = algebra.DIMENSIONS["r"]


@claim("s60r-dim-n-is-r", paper="adv", kind="id", sizes=admissible(n_max=3))
def n_is_r(s):
    """False (for r < n): tr(I_n) = tr(I_r)."""
    return {"tr In - tr Ir": s.tr(s.In) - s.tr(s.Ir)}
