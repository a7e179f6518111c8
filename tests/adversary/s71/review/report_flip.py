# ruff: noqa
"""Forge: the `fails` record of flip_false.py at (3,2) under modular made `checked` with the evidence of a true
claim's record (verdict, flag, certificate, bound, check statuses; witness and residual dropped).  The digest,
rerun, words and meta stay the false claim's own.
Run: S verify --claims R/flip_false.py --method modular --size 3,2 --jobs 1 --report-dir OUT
     S verify --claims R/flip_true.py --method modular --size 3,2 --jobs 1 --report-dir OUT_T
     python R/report_flip.py OUT/results.json OUT_T/results.json OUT/forged.json
     S report --results OUT/forged.json --report-dir OUT/rep ; S check OUT/forged.json"""
import json
import sys

src, true_src, out = sys.argv[1:4]
d = json.load(open(src))
t = json.load(open(true_src))["results"][0]
r = d["results"][0]
for k in ("verdict", "expected", "certificate", "residual", "false_pass_bound", "checks", "message"):
    r[k] = t[k]
r["witness"] = None
json.dump(d, open(out, "w"), indent=1)
