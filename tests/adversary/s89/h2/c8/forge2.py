# ruff: noqa: E702
"""Class 8, the standalone checker (python -m stiefelsym.certificate_check): certificates whose residual is
zero in disguise, attached to the FALSE claim c8-false (XXᵀ = I_n) with its own claim id and digest.
 g1 empty: residual [] and terms [] (the issue's route: must be rejected).
 g2 zero-coef: residual (0)·X Xt, terms [].
 g3 sym-zero: residual (n - n)·X Xt + (r - r)·I, terms [].
 g4 cancel: residual X Xt − X Xt written as two terms, terms [].
 g5 square: residual X Xt − I with hypothesis XXt (true at r = n only), record stated for all n, r.
 g6 zero-term-hyp: residual [] with a term of coefficient 0 on XtX.
 g7 no entries but a 'cases' format with an empty case list.
"""
import copy
import json
import os
import sys
base = json.load(open(sys.argv[1]))
def cert(residual, terms, hyps, realization="standard", typ=("n", "n")):
    return {"format": "stiefelsym-cofactor-1", "realization": realization,
            "symbols": {"n": "the dimension n (tr I_n)", "r": "the dimension r (tr I_r)"}, "letters": {},
            "entries": [{"position": "r[1,1]", "type": list(typ), "residual": residual, "terms": terms, "hypotheses": hyps}],
            "summary": {"entries": 1, "terms": len(terms), "hypotheses": hyps}}
def T(c, w): return {"coef": c, "traces": [], "word": w}
def H(c, h): return {"coef": c, "traces": [], "left": [], "hyp": h, "right": [], "in_trace": False, "word": []}
variants = {
 "g1": cert([], [], []),
 "g2": cert([T("0", ["X", "Xt"])], [], []),
 "g3": cert([T("n - n", ["X", "Xt"]), T("r - r", [])], [], []),
 "g4": cert([T("1", ["X", "Xt"]), T("-1", ["X", "Xt"])], [], []),
 "g5": cert([T("1", ["X", "Xt"]), T("-1", [])], [H("1", "XXt")], ["XXt"]),
 "g6": cert([], [H("0", "XtX")], ["XtX"], typ=("r", "r")),
}
for name, cd in list(variants.items()) + [("g7", {"format": "stiefelsym-cases-1", "cases": []})]:
    d = copy.deepcopy(base)
    r = next(x for x in d["results"] if x["claim"] == "c8-false" and x["method"] == "free")
    cd = copy.deepcopy(cd); cd["about"] = {"claim": "c8-false", "digest": r["digest"]}
    r.update(verdict="proved", certificate="cofactor certificate", certificate_data=cd)
    d["results"] = [r]
    os.makedirs(f"forged/{name}", exist_ok=True)
    json.dump(d, open(f"forged/{name}/results.json", "w"), indent=1)
print("ok")
