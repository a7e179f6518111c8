"""Free method: statements of sizes whose declarations lie (the fields say r = n or r = 1, the listed sizes or the
object say otherwise).  The free method takes X Xᵀ = I_n as a hypothesis on a family r = n, and the columns of
R^r at r = 1.

ly-replace-f   dataclasses.replace(admissible(n_max=3), r_is_n=True): listed sizes include r < n;
               residual X Xᵀ − I_n (FALSE at r < n, TRUE at r = n)
ly-setattr-f   object.__setattr__ on a frozen admissible(n_max=3) spec: r_in = ("n",) after the sizes were listed
ly-sub-f       a SizeSpec subclass whose admits() says r = n but iterates sizes with r < n
ly-where-f     admissible(n_max=3, r_is_n=True, where=<sets r_is_n False on itself when called>)
ly-r1-f        dataclasses.replace(admissible(n_max=3), r_min=1, r_max=1) with r > 1 listed; residual XᵀP (FALSE at r > 1)
"""
import dataclasses

from stiefelsym import admissible, claim
from stiefelsym.claims import SizeSpec


def _xxt(s):
    return {"x": s.X @ s.X.T - s.In}


claim("ly-replace-f", kind="id", sizes=dataclasses.replace(admissible(n_max=3), r_is_n=True))(_xxt)

_sp = admissible(n_max=3)
object.__setattr__(_sp, "r_in", ("n",))
claim("ly-setattr-f", kind="id", sizes=_sp)(_xxt)


class _Sub(SizeSpec):
    def admits(self, n, r):
        return r == n


claim("ly-sub-f", kind="id", sizes=_Sub(admissible(n_max=3).sizes, r_is_n=True))(_xxt)


def _flip(n, r):
    sp = globals().get("_sp2")
    if sp is not None:
        object.__setattr__(sp, "r_is_n", False)
    return True


_sp2 = admissible(n_max=3, r_is_n=True, where=_flip)
claim("ly-where-f", kind="id", sizes=_sp2)(_xxt)


@claim("ly-r1-f", kind="id", sizes=dataclasses.replace(admissible(n_max=3), r_min=1, r_max=1))
def r1_f(s):
    return {"x": s.X.T @ s.P}
