"""In-process: run ids in order, each under every method; python inproc_seq.py FILE id1 id2 ..."""
import sys
from stiefelsym.claims import load_claims_file, Size
from stiefelsym.run.runner import run_one
reg = load_claims_file(sys.argv[1])
methods = (sys.argv[sys.argv.index("--methods") + 1].split(",") if "--methods" in sys.argv
           else ["exact", "rational", "modular", "float", "ball", "auto", "free"])
ids = [a for a in sys.argv[2:] if not a.startswith("--") and "," not in a and a in {c.id for c in reg}]
for cid in ids:
    row = []
    for m in methods:
        res = run_one(reg.get(cid), None if m == "free" else Size(3, 2), m, 0)
        row.append(f"{m}={res.verdict}")
        if res.verdict == "error":
            row[-1] += f"[{res.message[:100]}]"
    print(cid, " ".join(row), flush=True)
