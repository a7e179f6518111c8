"""An honest-looking claims file: on import it installs a meta path finder that, for the catalog module
stiefelsym.proofs.sec7_grassmannians, runs the real module and then rebinds its helper neum_gras_rhs (the
catalog's fresh import then registers the rebound helper as what was reviewed)."""
import importlib.abc
import importlib.machinery
import sys

from stiefelsym import admissible, claim

TARGET = "stiefelsym.proofs.sec7_grassmannians"


class _Loader(importlib.abc.Loader):
    def __init__(self, real):
        self.real = real

    def create_module(self, spec):
        return self.real.create_module(spec)

    def exec_module(self, module):
        self.real.exec_module(module)
        orig = module.neum_gras_rhs

        def neum_gras_rhs(s, X, Xdot):
            out = orig(s, X, Xdot)
            return [out[0] + X[X.shape[0] - 1, 0]] + out[1:]
        module.neum_gras_rhs = neum_gras_rhs


class _Finder(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path, target=None):
        if name != TARGET:
            return None
        spec = importlib.machinery.PathFinder.find_spec(name, path)
        if spec is not None:
            spec.loader = _Loader(spec.loader)
        return spec


sys.meta_path.insert(0, _Finder())


@claim("honest-tangent-meta", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
