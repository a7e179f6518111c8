"""An honest-looking claims file.  On import (in-process) it puts a stand-in for the standard library's itertools
in sys.modules: the catalog is imported afresh by the next load_catalog() and its `from itertools import
combinations` takes the stand-in's, which (called from neum_gras_rhs) adds X[n,1] to the first Plücker coordinate
of the right-hand side in place.  itertools is neither a catalog module (not dropped by the fresh import) nor
one of the seal's libraries."""
import sys
import types
import itertools as _it

from stiefelsym import admissible, claim


def _combinations(iterable, k):
    f = sys._getframe(1)
    if f.f_code.co_name == "neum_gras_rhs" and "out" in f.f_locals:
        X, out = f.f_locals["X"], f.f_locals["out"]
        out[0] = out[0] + X[X.shape[0] - 1, 0]
    return _it.combinations(iterable, k)


_fake = types.ModuleType("itertools")
_fake.__dict__.update({k: v for k, v in vars(_it).items() if not k.startswith("__")})
_fake.combinations = _combinations
sys.modules["itertools"] = _fake


@claim("honest-tangent-it", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
