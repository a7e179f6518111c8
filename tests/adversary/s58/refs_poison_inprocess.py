"""In-process check that the poisoned refs cache of batch1.py fools the trace-time Inverse checks (run from this folder:
../../../.venv/bin/python refs_poison_inprocess.py): prints constant? ... -> True and traced N (no refusal)."""
import importlib
import sys

from stiefelsym.claims import load_claims_file
from stiefelsym.scene import REALIZATIONS

sys.path.insert(0, ".")
T = importlib.import_module("stiefelsym.ir.trace")
orig = T.Trace._constant


def dbg(self, a):
    g = self.g
    print("constant?", a, g.ops[a.i] if type(a) is T.Ref else a, g.args[a.i] if type(a).__name__ == "Ref" else "",
          type(g.cache.get("refs")), file=sys.stderr)
    out = orig(self, a)
    print(" ->", out, file=sys.stderr)
    return out


T.Trace._constant = dbg
reg = load_claims_file("batch1.py")
c = reg.get("s58-refs-inv-div-trace")
cons = REALIZATIONS["standard"]
try:
    g = T.trace(c.func, 3, 2, (cons.name, cons.build))
    print("traced", len(g.ops))
except Exception as e:  # noqa: BLE001 - a probe: print whatever it raised
    print("ERR", e)
