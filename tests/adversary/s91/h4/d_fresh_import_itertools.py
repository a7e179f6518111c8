# ruff: noqa
"""Point 2: my claims file loaded in-process first, then the catalog claim verified BY ID (the engine loads the
catalog afresh from disk itself)."""
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from common import run
stiefelsym.load_claims_file("evil_itertools_file.py")
run("d_fresh_import_itertools.py+evil_itertools_file.py", "neum-gras", [(3, 2)], sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "false")
