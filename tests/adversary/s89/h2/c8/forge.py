# ruff: noqa: E702
"""Class 8: forge free records of results.json by hand (no stiefelsym import); each variant is written to
its own folder forged/<name>/results.json, and then `stiefelsym report` / `check --no-rerun` / the checker run on it.

Variants (all target FALSE claims c8-false: XXᵀ = I_n, c8-false2: XᵀP = 0):
 f1 square-hyp: c8-false's free record made proved with a cofactor certificate in the hypothesis XXt
    (X Xᵀ = I_n, true only at r = n), the residual X Xᵀ − I_n written honestly.
 f2 replay-true: c8-true2's certificate (XᵀP + PᵀX) with 'about' and digest rewritten to c8-false2's,
    the residual left as c8-true2's.
 f3 replay-residual: as f2, and the residual written as c8-false2's real residual XᵀP, terms: ½(XtP+PtX)
    plus ½(XᵀP − PᵀX)... (no hypothesis for the second part: expected to be rejected by the checker).
 f4 metric: c8-false's free record proved by a certificate of realization 'metric' (hypothesis XtAinvP+PtAinvX),
    residual XXᵀ − I_n: algebraically impossible; tests whether realization is bound to the record.
 f5 dup-record: c8-false's free record made proved by copying c8-true's free record wholesale and changing
    only claim/title/rerun (digest left as c8-true's).
 f6 square-cases: as f1, but the record's 'realization' field set to 'square'.
"""
import copy
import json
import os
import sys

base = json.load(open(sys.argv[1]))
recs = base["results"]
def rec(cid, m):
    return next(r for r in recs if r["claim"] == cid and r["method"] == m)

def write(name, mutate):
    d = copy.deepcopy(base)
    mutate(d)
    os.makedirs(f"forged/{name}", exist_ok=True)
    json.dump(d, open(f"forged/{name}/results.json", "w"), indent=1, ensure_ascii=False)

def make_proved(r, cert_data, text):
    r["verdict"] = "proved"; r["certificate"] = text; r["certificate_data"] = cert_data
    r["checks"] = [{"name": "r", "status": "zero", "detail": "", "degree": None}]

def f1(d):
    r = next(x for x in d["results"] if x["claim"] == "c8-false" and x["method"] == "free")
    cd = {"format": "stiefelsym-cofactor-1", "realization": "standard",
          "symbols": {"n": "the dimension n (tr I_n)", "r": "the dimension r (tr I_r)"}, "letters": {},
          "entries": [{"position": "r[1,1]", "type": ["n", "n"],
                       "residual": [{"coef": "1", "traces": [], "word": ["X", "Xt"]}, {"coef": "-1", "traces": [], "word": []}],
                       "terms": [{"coef": "1", "traces": [], "left": [], "hyp": "XXt", "right": [], "in_trace": False, "word": []}],
                       "hypotheses": ["XXt"]}],
          "summary": {"entries": 1, "terms": 1, "hypotheses": ["XXt"]},
          "about": {"claim": "c8-false", "digest": r["digest"]}}
    make_proved(r, cd, "cofactor certificate of 1 residual entry (1 terms in the hypotheses XXt), re-checked by the independent checker")

def f2(d):
    t = next(x for x in d["results"] if x["claim"] == "c8-true2" and x["method"] == "free")
    r = next(x for x in d["results"] if x["claim"] == "c8-false2" and x["method"] == "free")
    cd = copy.deepcopy(t["certificate_data"]); cd["about"] = {"claim": "c8-false2", "digest": r["digest"]}
    make_proved(r, cd, t["certificate"]); r["derivation"] = t["derivation"]

def f3(d):
    r = next(x for x in d["results"] if x["claim"] == "c8-false2" and x["method"] == "free")
    cd = {"format": "stiefelsym-cofactor-1", "realization": "standard",
          "symbols": {"n": "the dimension n (tr I_n)", "r": "the dimension r (tr I_r)"}, "letters": {},
          "entries": [{"position": "r[1,1]", "type": ["r", "r"],
                       "residual": [{"coef": "1", "traces": [], "word": ["Xt", "P"]}],
                       "terms": [{"coef": "1/2", "traces": [], "left": [], "hyp": "XtP+PtX", "right": [], "in_trace": False, "word": []}],
                       "hypotheses": ["XtP+PtX"]}],
          "summary": {"entries": 1, "terms": 1, "hypotheses": ["XtP+PtX"]},
          "about": {"claim": "c8-false2", "digest": r["digest"]}}
    make_proved(r, cd, "cofactor certificate of 1 residual entry")

def f4(d):
    r = next(x for x in d["results"] if x["claim"] == "c8-false" and x["method"] == "free")
    f1(d)
    r["certificate_data"]["realization"] = "metric"
    e = r["certificate_data"]["entries"][0]
    e["terms"][0]["hyp"] = "XtAinvP+PtAinvX"; e["hypotheses"] = ["XtAinvP+PtAinvX"]

def f5(d):
    t = next(x for x in d["results"] if x["claim"] == "c8-true" and x["method"] == "free")
    i = next(i for i, x in enumerate(d["results"]) if x["claim"] == "c8-false" and x["method"] == "free")
    new = copy.deepcopy(t); old = d["results"][i]
    for k in ("claim", "title", "rerun", "traced"):
        new[k] = old[k]
    new["certificate_data"]["about"]["claim"] = "c8-false"
    d["results"][i] = new

def f6(d):
    f1(d)
    r = next(x for x in d["results"] if x["claim"] == "c8-false" and x["method"] == "free")
    r["realization"] = "square"

for name, f in [("f1", f1), ("f2", f2), ("f3", f3), ("f4", f4), ("f5", f5), ("f6", f6)]:
    write(name, f)
print("ok")
