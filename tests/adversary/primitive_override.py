"""A claims file that changes the verdict of a CATALOG claim, with the public API only:
``stiefelsym.ir.primitive`` registers a function under ``f.__module__ + "." + f.__qualname__``
(plain attributes, writable), overwriting the engine primitive of that name in the process-wide
table.  The catalog claim's graph names the primitive by that name only, so its digest is unchanged,
and every later evaluation (verify, and ``stiefelsym check``, which loads the claims files a
results file names) runs this file's function instead of the engine's.

    stiefelsym verify magnetic-form-kirillov-kostant --claims primitive_override.py --size 3,2 --method modular
"""
from stiefelsym import admissible, claim
from stiefelsym.ir import primitive
import stiefelsym.twisted  # noqa: F401  (the engine registers its primitive first; this file's comes after)


def form(s, u, v, F=None):
    """ω₀(u, v): the canonical form with the magnetic term dropped (not the engine's ω_ε)."""
    return s.tr(u["P"].T @ v["X"]) - s.tr(u["X"].T @ v["P"])


form.__module__ = "stiefelsym.twisted"
form.__qualname__ = "form"
primitive(form)


@claim("adv-honest", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def honest(s):
    """XᵀX = I (true): the file's own claim is honest."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}

