"""s60 review2: the seal reads each verdict module through sys.modules (stiefelsym/ir/seal.py, _fingerprint:
`mod = sys.modules.get(name)`), while the engine's functions read their own module's dict (`__globals__`).
This file puts in sys.modules a stand-in module object whose dict holds the very same attribute objects (so the
fingerprint, which names every attribute by identity and reads contents, is unchanged), then rebinds the public
`DIMENSIONS` of the real stiefelsym.free.algebra module (the free algebra's value of tr I_n) to a dict where
n = r.  No underscore name is written.  In-process, the dimension-free method proves tr I_n = tr I_r."""
import sys
import types

from stiefelsym import admissible, claim
from stiefelsym.free import algebra

_real = sys.modules["stiefelsym.free.algebra"]
stand_in = types.ModuleType(_real.__name__)
stand_in.__dict__.update(_real.__dict__)
# (control: no swap)
algebra.DIMENSIONS = dict(algebra.DIMENSIONS, n=algebra.DIMENSIONS["r"])


@claim("s60r2-noswap-control", paper="adv", kind="id", sizes=admissible(n_max=3))
def n_is_r(s):
    """False (for r < n): tr(I_n) = tr(I_r)."""
    return {"tr In - tr Ir": s.tr(s.In) - s.tr(s.Ir)}
