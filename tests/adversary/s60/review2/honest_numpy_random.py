"""An honest claims file (no engine write): it imports numpy.random (e.g. to make a fixed random test matrix
of its own) and states a true claim.  In-process its loading is refused by the seal (a false alarm): numpy is
fingerprinted (seal._LIBRARIES) and importing its submodule numpy.random, not yet imported when the engine was
sealed, adds the module attribute numpy.random."""
import numpy.random

from stiefelsym import admissible, claim

SHIFT = int(numpy.random.default_rng(0).integers(1, 5))


@claim("s60r2-honest-npr", paper="adv", kind="id", sizes=admissible(n_max=3))
def xtx(s):
    """True: XᵀX = I_r (scaled by the file's own number)."""
    return {"XtX - I": SHIFT * (s.X.T @ s.X - s.Ir)}
