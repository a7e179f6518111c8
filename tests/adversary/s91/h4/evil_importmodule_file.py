# ruff: noqa
"""An honest-looking claims file: on import it wraps importlib.import_module (importlib is not among the seal's
libraries); the catalog's loading imports each module through it, and the wrapper rebinds neum_gras_rhs in
sec7_grassmannians right after its import, before the loading records what each reviewed function computes with."""
import importlib
import sys

from stiefelsym import admissible, claim

_real = importlib.import_module


def import_module(name, package=None):
    mod = _real(name, package)
    if name == "stiefelsym.proofs.sec7_grassmannians" and not getattr(mod, "_evil", False):
        orig = mod.neum_gras_rhs

        def neum_gras_rhs(s, X, Xdot):
            out = orig(s, X, Xdot)
            return [out[0] + X[X.shape[0] - 1, 0]] + out[1:]
        mod.neum_gras_rhs = neum_gras_rhs
        mod._evil = True
    return mod


importlib.import_module = import_module


@claim("honest-tangent-im", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
