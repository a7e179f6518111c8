"""In-process: python inproc.py FILE [--methods m1,m2] [--size n,r]: every claim of FILE under each method."""
import sys
from stiefelsym.claims import load_claims_file, Size
from stiefelsym.run.runner import run_one
reg = load_claims_file(sys.argv[1])
methods = (sys.argv[sys.argv.index("--methods") + 1].split(",") if "--methods" in sys.argv
           else ["exact", "rational", "modular", "float", "ball", "auto", "free"])
size = (tuple(int(x) for x in sys.argv[sys.argv.index("--size") + 1].split(",")) if "--size" in sys.argv else (3, 2))
for c in reg:
    row = []
    for m in methods:
        res = run_one(c, None if m == "free" else Size(*size), m, 0)
        row.append(f"{m}={res.verdict}")
        if res.verdict == "error":
            row[-1] += f"[{res.message[:100]}]"
    print(c.id, " ".join(row), flush=True)
