# ruff: noqa
import sys, atexit, json
def dump():
    ms = sorted(m for m in sys.modules if m.startswith("stiefelsym"))
    with open(sys.argv[0] + ".mods", "w") as f:
        json.dump(ms, f)
atexit.register(dump)
args = sys.argv[1:]
sys.argv = ["stiefelsym"] + args
sys.argv[0] = __file__
from stiefelsym.cli import main
try:
    rc = main()
finally:
    dump()
sys.exit(rc)
