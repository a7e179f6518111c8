"""A false claim proved by every method, the dimension-free one included: the claims file is imported
into the engine's process and rewrites the evaluator's table of subtractions (``stiefelsym.ir.evaluate.
_ARITH``), so x − y evaluates as x − x for every claim of the run (the catalog's included)."""
import operator

from stiefelsym import admissible, claim
from stiefelsym.ir.evaluate import _ARITH

_ARITH["sub"] = lambda x, y: operator.sub(x, x)


@claim("adv-evaluator", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def x_equals_2x(s):
    """X = 2X on the Stiefel variety (false)."""
    return {"X - 2X": s.X - s.X * 2}
