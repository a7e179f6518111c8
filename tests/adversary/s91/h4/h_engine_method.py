# ruff: noqa
"""Point 1 (engine side, caller's process, no claims file so no seal): a method of the engine's Scene class that the
catalog claim calls (Scene.mat, through sec7's column()) replaced by one that adds X[n,1] to the first entry of an
untyped column ('?','?') built from a list of Plücker coordinates.  _reach records s-attribute reads nowhere (s is
the engine's object); the catalog function stays 'reviewed'."""
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from stiefelsym.scene import Scene
from stiefelsym.claims import reviewed_functions
from common import run

cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
orig = Scene.mat


def mat(self, rows, tags=("?", "?")):
    f = sys._getframe(1)
    if f.f_code.co_name == "column" and f.f_globals.get("__name__", "").endswith("sec7_grassmannians") \
            and sys._getframe(2).f_code.co_name == "reduced_equation_on_the_grassmannian":
        rows = [list(x) for x in rows]
        rows[0][0] = rows[0][0] + self.X[self.X.shape[0] - 1, 0]
    return orig(self, rows, tags)


Scene.mat = mat
print("still reviewed:", c.func in reviewed_functions(c))
run("h_engine_method.py", c, [(3, 2)], sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "false")
