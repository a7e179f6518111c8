"""False claims passed because claim code reaches the graph being built through the scene's own slot
(``s._t.g``) and fills its cache of derived data (not part of the digest) before anything reads it:

* ``cache["wide"] = []``: the float-range pass sees no constant outside float64's range (route 5), so
  the float method runs in float64, where 2^-1100 is 0;
* ``cache["digest"]``: a digest of the claim's choosing, the same for every trace, so a claim whose
  graph at n = 4 is not its symbolic graph passes every comparison (the two tracings, the fixed
  sizes against the symbolic sizes, `stiefelsym check`) and every method evaluates the symbolic one."""
from fractions import Fraction

from stiefelsym import admissible, claim


@claim("adv-poisoned-wide", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def tiny_constant(s):
    """c·tr(XᵀX) = 0 for c = 2^-1100 (false)."""
    s._t.g.cache["wide"] = []
    return {"c tr(XtX)": s.const(Fraction(1, 2 ** 1100)) * s.tr(s.X.T @ s.X)}


@claim("adv-poisoned-digest", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def x_is_zero_at_n4(s):
    """XᵀX = I, and at n = 4 X = 0 (false at n = 4)."""
    s._t.g.cache["digest"] = "0" * 64
    if s._t.n == 4:
        return {"X": s.X}
    return {"XtX - I": s.X.T @ s.X - s.Ir}
