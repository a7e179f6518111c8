# ruff: noqa
"""Point 3: my file loaded in-process, then the catalog: my claim is in the catalog's reviewed registry."""
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from common import run, random_point
stiefelsym.load_claims_file("evil_audit_file.py")
cat = stiefelsym.load_catalog()
print("in the catalog:", "zz-smuggled" in cat, "| reviewed:", "zz-smuggled" in cat and cat.get("zz-smuggled").reviewed)
X, P = random_point(3, 2)
print("truth: last row of X at a random point:", X[2])
run("f_audit_smuggle.py+evil_audit_file.py", "zz-smuggled", [(3, 2), (4, 2)], sys.argv[1].split(",") if len(sys.argv) > 1 else ["exact", "modular"], "false")
