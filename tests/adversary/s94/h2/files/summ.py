import json
import sys
from collections import defaultdict
d = json.load(open(sys.argv[1]))
agg = defaultdict(list)
for r in d["results"]:
    spec = "S" if any("specialised" in x for x in (r.get("reductions") or [])) else ""
    agg[(r["claim"], r.get("variant") or "")].append(f"{r.get('n')},{r.get('r')}:{r['method'][:3]}:{r['verdict'][:4]}{spec}")
for k, v in agg.items():
    print(k, " ".join(v))
