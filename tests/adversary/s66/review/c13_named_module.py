# ruff: noqa
"""A claim whose graph names an engine step of a module that does not exist (yet): stiefelsym.zz_evil.step.
In the child, the step node is made through the trace's own (private) prim door.  The verifying process's replay
(stiefelsym/ir/replay.py _registered) looks the module name up on disk (seal.engine_module_of walks the package
folder) and imports it if a file of that name is there when the graph is replayed."""
from stiefelsym import admissible, claim
import sys
import stiefelsym.ir.trace
_T = sys.modules["stiefelsym.ir.trace"]

S = admissible(n_min=3, n_max=3, r_in=(2,))


@claim("c13-names-a-module", kind="id", sizes=S)
def names_module(s):
    """false: X^T P = 0 (the graph also holds one step node naming stiefelsym.zz_evil.step)."""
    _T._ACTIVE[-1].prim("stiefelsym.zz_evil.step", (s,), {})
    return {"x": s.X.T @ s.P}
