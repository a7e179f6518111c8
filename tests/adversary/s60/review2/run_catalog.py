"""python run_catalog.py FILE CLAIM_ID n,r methods: load FILE in-process (load_claims_file), run its claims, then
load the paper's catalog in the same process (load_catalog) and run CLAIM_ID."""
import sys
from stiefelsym.claims import load_catalog, load_claims_file, Size
from stiefelsym.run.runner import run_one
path, cid = sys.argv[1], sys.argv[2]
size = Size(*map(int, sys.argv[3].split(",")))
methods = sys.argv[4].split(",")
if path != "-":
    for c in load_claims_file(path):
        print("file:", c.id, run_one(c, size, "modular", 0).verdict, flush=True)
cat = {c.id: c for c in load_catalog()}
c = cat[cid]
for m in methods:
    r = run_one(c, None if m == "free" else size, m, 0)
    print(f"catalog: {cid} {m}={r.verdict} expected={r.expected} {'' if r.verdict != 'error' else r.message[:150]}",
          flush=True)
