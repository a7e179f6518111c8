"""Helper (not a claims file): which traces of a claims file the exact method reassociates, per claim.
usage: python fused_nodes.py FILE n r"""
import importlib.util
import sys

from stiefelsym.ir import compile_claim
from stiefelsym.ir.evaluate import _deps, _paired_products, _trace_products
from stiefelsym.scene import REALIZATIONS

path, n, r = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
spec = importlib.util.spec_from_file_location("probe", path)
mod = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mod)
cons = REALIZATIONS["standard"]
for name, f in vars(mod).items():
    if callable(f) and getattr(f, "__module__", "") == "probe" and not name.startswith("_"):
        try:
            g = compile_claim(f, n, r, (cons.name, cons.build))
        except Exception as exc:  # noqa: BLE001
            print(name, "not compiled:", type(exc).__name__, str(exc)[:100])
            continue
        pp = _paired_products(g, _deps(g))
        print(name, "paired:", {i: (v[3], len(v[2]), len(v[4])) for i, v in pp.items()}, "trace_products:", len(_trace_products(g, _deps(g))))
