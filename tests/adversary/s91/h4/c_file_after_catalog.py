# ruff: noqa
"""Notebook order: the catalog, then my claims file in-process (load_claims_file, seal checked), then the catalog
claim object I hold."""
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from common import run
cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
reg = stiefelsym.load_claims_file("evil_zip_file.py")
print("file loaded:", reg.ids(), "| neum-gras reviewed:", c.reviewed)
run("c_file_after_catalog.py+evil_zip_file.py", c, [(3, 2), (4, 2)], sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "false")
