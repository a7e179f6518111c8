import sys
import stiefelsym
from stiefelsym.claims import Size
from stiefelsym.run.runner import run_one
reg = stiefelsym.load(sys.argv[1])
for c in reg:
    print(c.id, [ (m, run_one(c, None if m == "free" else Size(3, 2), m, 0).verdict) for m in ("free", "modular", "exact")])
