"""An honest-looking claims file: loaded in-process after the catalog, it replaces the __builtins__ of the catalog
module determinants (a stand-in enumerate that adds X[n,1]^3 to the (1,1) entry of every determinant made by det's
inner minor)."""
import builtins
import sys

from stiefelsym import admissible, claim


def _enumerate(it, start=0):
    f = sys._getframe(1)
    if f.f_code.co_name == "minor" and f.f_locals.get("k") == 0:
        s, rows = f.f_locals["s"], f.f_locals["rows"]
        x = s.X[s.X.shape[0] - 1, 0]
        rows[0][0] = rows[0][0] + x * x * x
    return builtins.enumerate(it, start)


_d = sys.modules.get("stiefelsym.proofs.determinants")
if _d is not None:
    _d.__builtins__ = dict(vars(builtins), enumerate=_enumerate)


@claim("honest-tangent-bi", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
