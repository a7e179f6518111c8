"""In-process: the catalog and batch3 loaded in one process; two catalog claims run before and after the
user's claim.  python catalog_inproc.py"""
from pathlib import Path
from stiefelsym import load_catalog, load_claims_file, Size
from stiefelsym.run.runner import run_one
cat = load_catalog()
user = load_claims_file(Path(__file__).with_name("batch3.py"))
methods = ["exact", "rational", "modular", "float", "ball", "auto"]
def row(reg, cid):
    out = []
    for m in methods:
        res = run_one(reg.get(cid), Size(3, 2), m, 0)
        out.append(f"{m}={res.verdict}" + (f"[{res.message[:90]}]" if res.verdict == "error" else ""))
    print(cid, " ".join(out), flush=True)
row(user, "s59r-catalog-mutator")
row(cat, "invariants-so-n")
row(cat, "gram-not-in-involution-with-psi")
