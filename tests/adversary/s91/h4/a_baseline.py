# ruff: noqa
"""Baseline: the catalog's neum-gras untouched (true)."""
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from common import run
cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
print("reviewed:", c.reviewed)
run("a_baseline.py", c, [(3, 2)], sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "true")
