# ruff: noqa
"""Point 1: the catalog module determinants' __builtins__ replaced after the catalog was loaded (in the caller's
process).  Functions created at call time (det's inner memoized `minor`, a closure made at each call) take their
builtins from their module's globals['__builtins__']; _reach records the builtins a function reads as
vars(builtins)[name], and '__builtins__' is no name a code object reads, so nothing recorded changes.  The evil
enumerate (called by minor at k = 0) adds X[n,1]^3 to the (1,1) entry of every determinant: the Plücker
coordinates of (neum-gras) then carry X[n,1]^3 terms (zero with two derivatives at X = X0 only): FALSE."""
import builtins, sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from stiefelsym.claims import reviewed_functions
from common import run

cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
d = sys.modules["stiefelsym.proofs.determinants"]


def enumerate(it, start=0):
    f = sys._getframe(1)
    if f.f_code.co_name == "minor" and f.f_locals.get("k") == 0:
        s, rows = f.f_locals["s"], f.f_locals["rows"]
        x = s.X[s.X.shape[0] - 1, 0]
        rows[0][0] = rows[0][0] + x * x * x
    return builtins.enumerate(it, start)


d.__builtins__ = dict(vars(builtins), enumerate=enumerate)
print("still reviewed:", c.func in reviewed_functions(c))
run("g_module_builtins.py", c, [(3, 2)], sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "false")
