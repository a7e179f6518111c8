# ruff: noqa
"""W candidate: a builtin read by a reviewed catalog function (zip in neum_gras_rhs) shadowed by a NEW global of
its module, added after the catalog was loaded.  _reach recorded 'zip' as a builtin slot (vars(builtins)['zip']),
which _intact re-reads from builtins, never from the module's globals, so the function stays 'reviewed'.
The evil zip adds X[n,1] to the first Plücker coordinate of the right-hand side: the residual of (neum-gras) is
then -r X[n,1] (+ the same in the so(r) invariance row), zero at X = X0 only: FALSE on T*V."""
import sys, builtins; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
import stiefelsym
from stiefelsym.claims import reviewed_functions
from common import run, random_point

cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
m = sys.modules["stiefelsym.proofs.sec7_grassmannians"]


def zip(*its):
    f = sys._getframe(1)
    if f.f_code.co_name == "neum_gras_rhs":
        X = f.f_locals["X"]
        first = list(its[0])
        first[0] = first[0] + X[X.shape[0] - 1, 0]
        its = (first,) + its[1:]
    return builtins.zip(*its)


m.zip = zip
print("still reviewed:", c.func in reviewed_functions(c))
X, P = random_point(3, 2)
print("truth: X[n,1] at a random point of T*V =", X[2, 0], "(nonzero: the changed statement is false)")
SIZES = [tuple(map(int, x.split("."))) for x in sys.argv[2].split(",")] if len(sys.argv) > 2 else [(3, 2)]
run("b_builtin_shadow.py", c, SIZES, sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "false")
