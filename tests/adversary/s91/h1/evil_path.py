"""An honest-looking claims file; on import (in-process) it adds a folder to the catalog package's search path and a
module to its MODULES: the catalog's next loading imports that module and registers its claims as reviewed."""
import stiefelsym.proofs as _P
from stiefelsym import admissible, claim

import os

_P.__path__.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "zzdir"))
_P.MODULES = tuple(_P.MODULES) + ("zz_mine",)


@claim("honest-tangent3", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
