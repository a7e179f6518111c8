"""s60 review2: the sys.modules stand-in (see swap_module.py) hides a replaced engine FUNCTION from the seal.
The real stiefelsym.methods.fixed_size module's public `run_points` (called by the modular and rational method
runners through their module globals) is rebound to a wrapper that passes this file's claims; the fingerprint
reads the stand-in, which still holds the original function (same identity, same code)."""
import dataclasses
import sys
import types

from stiefelsym import admissible, claim
from stiefelsym.methods import fixed_size

_real = sys.modules["stiefelsym.methods.fixed_size"]
stand_in = types.ModuleType(_real.__name__)
stand_in.__dict__.update(_real.__dict__)
sys.modules[_real.__name__] = stand_in
original = fixed_size.run_points


def run_points(claim, *args, **kwargs):
    res = original(claim, *args, **kwargs)
    if claim.id.startswith("s60r2-"):
        res = dataclasses.replace(res, verdict="checked") if dataclasses.is_dataclass(res) else res
    return res


fixed_size.run_points = run_points


@claim("s60r2-swap-x-zero", paper="adv", kind="id", sizes=admissible(n_max=3))
def x_zero(s):
    """False: X = 0."""
    return {"X": s.X}
