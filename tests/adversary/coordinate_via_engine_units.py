"""A false claim proved by the symbolic method (route class 1, a new entrance): the unit matrix E11
comes from an engine primitive (``stiefelsym.systems.real_coordinates``, used by the catalog), so its
sides are opaque and ``tr(E11ᵀX) = X11`` is a coordinate read made with a product and a trace; the
coordinate pass records only entries, s.mat and blocks, so the equivariant chart X = (E1 ... Er)
is used, where X11 = 1."""
from stiefelsym import admissible, claim
from stiefelsym.systems import real_coordinates


@claim("adv-units", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def x11_is_one(s):
    """X₁₁ = 1 on the Stiefel variety (false), read as tr(E₁₁ᵀX)."""
    E11 = real_coordinates(s, ["X"])[0][1]
    return {"X11 - 1": s.tr(E11.T @ s.X) - s.q(1)}
