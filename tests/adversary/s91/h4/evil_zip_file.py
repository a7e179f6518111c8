"""An honest-looking claims file.  Loaded in-process AFTER the catalog, it adds a global 'zip' to the catalog module
sec7_grassmannians (shadowing the builtin that neum_gras_rhs reads): the catalog is not sealed, and _intact
re-reads builtins.zip, not the module's globals."""
import builtins
import sys

from stiefelsym import admissible, claim

_m = sys.modules.get("stiefelsym.proofs.sec7_grassmannians")


def _zip(*its):
    f = sys._getframe(1)
    if f.f_code.co_name == "neum_gras_rhs":
        X = f.f_locals["X"]
        first = list(its[0])
        first[0] = first[0] + X[X.shape[0] - 1, 0]
        its = (first,) + its[1:]
    return builtins.zip(*its)


if _m is not None:
    _m.zip = _zip


@claim("honest-tangent-zip", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
