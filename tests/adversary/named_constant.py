"""A false claim proved (exact, free) and numeric (float): ``stiefelsym.ir.named`` (public) registers any
object as an engine constant; the graph holds only its name, and the evaluator hands the object itself
to each method's arithmetic.  A Fraction subclass passes the exact-constant checks of the matrices (they
test issubclass), and its numerator, read when each number system converts it, looks at who asks."""
import sys
from fractions import Fraction
from stiefelsym import admissible, claim
from stiefelsym.ir import named


class _Shifty(Fraction):
    """1, except to the symbolic and float number systems, where it is 0."""
    @property
    def numerator(self):
        f = sys._getframe(1)
        while f is not None:
            q = f.f_code.co_qualname
            if q.startswith(("FloatField.", "SymbolicField.", "FreeField")):
                return 0
            f = f.f_back
        return 1

    @property
    def denominator(self):
        return 1


C = named("stiefelsym.adversary.c", _Shifty(1))


@claim("adv-named-shifty", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def shifty(s):
    """c·X = 0 for c = 1 (false)."""
    return {"cX": s.X * C}
