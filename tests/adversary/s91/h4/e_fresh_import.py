# ruff: noqa
"""Point 2: my claims file (argv[1]) loaded in-process first, then the catalog claim verified BY ID."""
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from common import run
f = sys.argv[1]
try:
    stiefelsym.load_claims_file(f"{f}")
    print("loaded", f)
except stiefelsym.CatalogError as e:
    print("REFUSED", str(e)[:300])
    sys.exit()
run(f"e_fresh_import.py+{f}", "neum-gras", [(3, 2)], sys.argv[2].split(",") if len(sys.argv) > 2 else ["exact", "modular"], "false")
