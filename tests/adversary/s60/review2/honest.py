"""Review helper: python honest.py FILE [methods] [n,r]: load an honest claims file in-process and run every claim
under each method; report any error that names the seal ("the engine was changed")."""
import sys
from stiefelsym.claims import load_claims_file, Size
from stiefelsym.run.runner import run_one
reg = list(load_claims_file(sys.argv[1]))
methods = sys.argv[2].split(",") if len(sys.argv) > 2 else ["modular", "float", "exact", "free"]
size = Size(*map(int, sys.argv[3].split(","))) if len(sys.argv) > 3 else Size(3, 2)
print("numpy.random loaded at start:", "numpy.random" in sys.modules)
for c in reg:
    out = []
    for m in methods:
        r = run_one(c, None if m == "free" else size, m, 0)
        flag = " <-- SEAL FALSE ALARM" if "engine was changed" in (r.message or "") else ""
        out.append(f"{m}={r.verdict}{flag}")
    print(c.id, " ".join(out), flush=True)
