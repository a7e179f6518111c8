"""In-process runner: python inproc.py FILE [ids...] -- runs every method at (3,2) and free."""
import sys
from stiefelsym.claims import load_claims_file, Size
from stiefelsym.run.runner import run_one
path = sys.argv[1]
reg = load_claims_file(path)
ids = sys.argv[2:] or [c.id for c in reg]
methods = ["exact", "rational", "modular", "float", "ball", "auto"]
for cid in ids:
    row = []
    for m in methods:
        res = run_one(reg.get(cid), Size(3, 2), m, 0)
        row.append(f"{m}={res.verdict}")
        if res.verdict == "error":
            row[-1] += f"[{res.message[:80]}]"
    res = run_one(reg.get(cid), None, "free", 0)
    row.append(f"free={res.verdict}")
    print(cid, " ".join(row), flush=True)
