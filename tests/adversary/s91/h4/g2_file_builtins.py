# ruff: noqa
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from common import run
c = stiefelsym.load_catalog().get("neum-gras")
stiefelsym.load_claims_file("evil_builtins_file.py")
print("reviewed:", c.reviewed)
run("g2_file_builtins.py+evil_builtins_file.py", c, [(3, 2), (4, 2)], sys.argv[1].split(","), "false")
