"""A false claim passed by the methods that build their scene before the claim is traced: claim code,
run on tracers, finds the method's live engine scene among the interpreter's objects
(``gc.get_objects()``), so it sees the method (and could read the point).  Traced twice under the same
scene, both graphs agree; the graph is then cached for the process."""
import gc

from stiefelsym import admissible, claim
from stiefelsym.scene import Scene


def _live_scene():
    return any(isinstance(o, Scene) for o in gc.get_objects())


@claim("adv-live-scene", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def x_is_zero(s):
    """X = 0 on the Stiefel variety (false)."""
    return {"X": s.X - s.X if _live_scene() else s.X}
