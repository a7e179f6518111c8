"""A false claim checked (and every claim of the process with it, the catalog's included): the claims
file registers a whole-matrix backend for GF(p) through ``stiefelsym.backends.native.register_backend`` (the
public hook the engine's own modules use); its zero test says yes to every matrix."""
from stiefelsym import admissible, claim
from stiefelsym.backends.fields import ModularField
from stiefelsym.backends.native import ModularBackend, register_backend


class _Backend(ModularBackend):
    def is_zero(self, a):
        return True


register_backend(ModularField, _Backend)


@claim("adv-backend", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def x_is_zero(s):
    """X = 0 on the Stiefel variety (false)."""
    return {"X": s.X}
