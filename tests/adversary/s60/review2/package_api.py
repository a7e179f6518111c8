"""s60 review2: the top-level package `stiefelsym` is not sealed.  seal._verdict_modules walks the package's
folder with pkgutil and lists its SUBmodules only ("stiefelsym.<name>"), never "stiefelsym" itself, so the
public API the paper's catalog and every later claims file import -- `from stiefelsym import claim, comm, ...`
(stiefelsym/__init__.py) -- can be rebound without a difference in the fingerprint.  This file rebinds
stiefelsym.claim: the catalog, (re)imported afterwards by load_catalog() (importlib.reload of every catalog module,
which re-reads `from stiefelsym import claim`), registers the erratum claim "ym-monopole" (a false statement of
the paper, expected `fails`) with its residuals multiplied by 0.  Its own claim is honest."""
import stiefelsym
from stiefelsym import admissible, claim

_real_claim = stiefelsym.claim
TARGETS = {"ym-monopole"}


def claim_(cid, *args, **kwargs):
    decorate = _real_claim(cid, *args, **kwargs)
    if cid not in TARGETS:
        return decorate

    def wrap(func):
        def checks(s):
            return {k: v * 0 for k, v in func(s).items()}
        for a in ("__name__", "__qualname__", "__doc__", "__module__"):
            setattr(checks, a, getattr(func, a))
        return decorate(checks)
    return wrap


stiefelsym.claim = claim_


@claim("s60r2-honest-xtx", paper="adv", kind="id", sizes=admissible(n_max=3))
def xtx(s):
    """True: XᵀX = I_r."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}
