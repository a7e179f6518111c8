# ruff: noqa
"""Point 1, time of check: a helper of the catalog module rebound in the caller's process by a wrapper that computes
the changed right-hand side (+ X[n,1]) and puts the original back in the module at its 4th call, i.e. once the run
has traced the claim twice (2 calls per tracing: the right-hand side, then the so(r) invariance row; the two graphs
agree, so the determinism check passes), and before the exact method asks whether the function is as reviewed:
_intact reads the module after the tracing, and the graph that is evaluated is the traced one."""
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from stiefelsym.claims import reviewed_functions
from common import run

cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
m = sys.modules["stiefelsym.proofs.sec7_grassmannians"]
orig = m.neum_gras_rhs
calls = [0]


def neum_gras_rhs(s, X, Xdot):
    calls[0] += 1
    if calls[0] >= 4:
        m.neum_gras_rhs = orig         # the module as it was reviewed, once the claim's function is done with it
    out = orig(s, X, Xdot)
    return [out[0] + X[X.shape[0] - 1, 0]] + out[1:]


m.neum_gras_rhs = neum_gras_rhs
print("reviewed now (rebound):", c.func in reviewed_functions(c))
run("l_toctou.py", c, [(3, 2)], sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "false")
print("reviewed after the runs in this process:", c.func in reviewed_functions(c))
