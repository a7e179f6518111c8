# ruff: noqa: E701, E702
"""Forge results files from logs/c8_base.json (class 8).  Each forged file keeps the claim's own words and digest."""
import copy
import json

base = json.load(open("/tmp/s86h1/out/logs/c8_base.json"))
R = base["results"]
def rec(cid, m):
    return next(r for r in R if r["claim"] == cid and r["method"] == m)
def out(name, records, meta=None):
    d = copy.deepcopy(base)
    d["results"] = records
    if meta:
        d["meta"].update(meta)
    json.dump(d, open(f"/tmp/s86h1/out/c8/{name}.json", "w"), indent=1)

EVID = ("verdict", "expected", "certificate", "residual", "false_pass_bound", "checks", "witness", "message", "seed",
        "reductions", "seconds")
# f1: b8-false exact fails -> proved, evidence copied from b8-true exact
f = copy.deepcopy(rec("b8-false", "exact")); t = rec("b8-true", "exact")
for k in EVID: f[k] = copy.deepcopy(t[k])
recs = [copy.deepcopy(r) for r in R if not (r["claim"] == "b8-false" and r["method"] == "exact")] + [f]
out("f1_fixed_verdict", recs)
# f2: b8-false modular fails -> checked, evidence from b8-true modular (seed kept)
f = copy.deepcopy(rec("b8-false", "modular")); t = rec("b8-true", "modular")
for k in EVID: f[k] = copy.deepcopy(t[k])
recs = [copy.deepcopy(r) for r in R if not (r["claim"] == "b8-false" and r["method"] == "modular")] + [f]
out("f2_modular_verdict", recs)
# f3: b8-false free undecided -> proved with b8-true's certificate_data
f = copy.deepcopy(rec("b8-false", "free")); t = rec("b8-true", "free")
for k in EVID + ("certificate_data", "derivation"): f[k] = copy.deepcopy(t[k])
recs = [copy.deepcopy(r) for r in R if not (r["claim"] == "b8-false" and r["method"] == "free")] + [f]
out("f3_free_cert", recs)
# f4: drop the b8-false records altogether, meta says only b8-true etc were run? keep meta; (missing runs)
recs = [copy.deepcopy(r) for r in R if r["claim"] != "b8-false"]
out("f4_dropped_claim", recs)
# f5: meta claims --max-n instead of sizes, drop the b8-false exact record only
recs = [copy.deepcopy(r) for r in R if not (r["claim"] == "b8-false" and r["method"] == "exact")]
out("f5_dropped_run", recs)
# f6: a record of b8-false exact swapped with expect="nonzero" (its field) and verdict proved
f = copy.deepcopy(rec("b8-false", "exact")); f["expect"] = "nonzero"; f["verdict"] = "proved"; f["expected"] = True
recs = [copy.deepcopy(r) for r in R if not (r["claim"] == "b8-false" and r["method"] == "exact")] + [f]
out("f6_expect_nonzero", recs)
# f7: b8-false exact duplicated: the genuine fails and a forged proved
f = copy.deepcopy(rec("b8-false", "exact"));  t = rec("b8-true", "exact")
for k in EVID: f[k] = copy.deepcopy(t[k])
recs = [copy.deepcopy(r) for r in R] + [f]
out("f7_duplicate_record", recs)
# f8: meta methods lists only modular and free; b8-false's exact record forged
f = copy.deepcopy(rec("b8-false", "exact")); t = rec("b8-true", "exact")
for k in EVID: f[k] = copy.deepcopy(t[k])
recs = [copy.deepcopy(r) for r in R if not (r["claim"] == "b8-false" and r["method"] == "exact")] + [f]
out("f8_meta_methods", recs, {"methods": ["exact", "modular", "free"]})
