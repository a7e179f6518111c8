# ruff: noqa
"""Hand-edit a results.json: the rerun command of every failing record.
python forge_rerun.py MODE IN OUT
  size   -- --size of the rerun changed to another admitted size (3,3)
  method -- the rerun's method changed (exact -> modular)
  extra  -- a harmless extra word, so the rerun joins no group
  quote  -- the claim id in the rerun replaced by another claim's id
"""
import json, sys
mode, src, dst = sys.argv[1:4]
d = json.load(open(src))
for r in d["results"]:
    if r["verdict"] != "fails" or not r.get("rerun"):
        continue
    if mode == "size":
        r["rerun"] = r["rerun"].replace(f"--size {r['n']},{r['r']}", "--size 3,3")
    elif mode == "method":
        r["rerun"] = r["rerun"].replace("--method exact", "--method modular")
    elif mode == "extra":
        r["rerun"] = r["rerun"] + " --hard"
    elif mode == "quote":
        r["rerun"] = r["rerun"].replace("verify mm-trace", "verify mm-momentum")
json.dump(d, open(dst, "w"), indent=1)
