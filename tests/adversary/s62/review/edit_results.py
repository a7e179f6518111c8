# ruff: noqa: F841, E702
"""Hand-edited copies of out/rep/results.json (written by
`stiefelsym verify --claims tests/adversary/s62/review/edit_claims.py --method exact --jobs 1 --report-dir tests/adversary/s62/review/out/rep`)."""
import copy
import json
base = json.load(open("out/rep/results.json"))


def write(name, d):
    json.dump(d, open(f"out/rep/{name}.json", "w"), indent=1)


def rec(d, cid):
    return next(r for r in d["results"] if r["claim"] == cid)


d = copy.deepcopy(base); rec(d, "ed-false")["expected"] = True; write("forged_expected", d)
d = copy.deepcopy(base); f, t = rec(d, "ed-false"), rec(d, "ed-true")
f.update(verdict="proved", expected=True, witness=None, residual=None, seed=None, certificate=t["certificate"],
         reductions=t["reductions"], checks=[dict(c, status=t["checks"][0]["status"]) for c in f["checks"]], rerun="")
write("forged_proved", d)
d = copy.deepcopy(base); d["results"] = [r for r in d["results"] if r["claim"] != "ed-false"]
d["meta"]["command"] = d["meta"]["command"].replace("edit_claims.py", "edit_claims.py ed-true")
write("forged_dropped_named", d)
d = copy.deepcopy(base); d["results"] = [r for r in d["results"] if r["claim"] != "ed-false"]
write("forged_dropped", d)
d = copy.deepcopy(base); rec(d, "ed-false")["message"] = "all is well"; rec(d, "ed-false")["erratum"] = "misprint"
write("forged_erratum", d)
print("written")
