# ruff: noqa: E401, E701, E702
import json, collections, sys
tag, truthf = sys.argv[1], sys.argv[2]
truth = json.load(open(truthf))
v = collections.defaultdict(dict)
for m in ["exact", "rational"]:
    for r in json.load(open(f"logs/{tag}_{m}.json"))["results"]:
        v[(r["claim"], r["n"], r["r"])][m] = r["verdict"]
dis = 0; cnt = collections.Counter()
for k, d in sorted(v.items()):
    e, ra = d["exact"], d["rational"]
    cnt[(truth[k[0]], e, ra)] += 1
    if (e == "proved") != (ra in ("checked", "proved")) or e == "error":
        dis += 1; print("DISAGREE", k, d)
    if not truth[k[0]] and e == "proved": print("false-by-construction but proved:", k)
    if truth[k[0]] and e != "proved": print("true but not proved:", k, d)
print(dict(cnt)); print("disagreements", dis)
