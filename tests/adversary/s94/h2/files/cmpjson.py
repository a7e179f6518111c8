import json
import sys
import hashlib
def load(p):
    try:
        d = json.load(open(p))
    except Exception as e:
        print("cannot read", p, e); return {}
    out = {}
    for r in d["results"]:
        k = (r["claim"], r.get("variant"), r.get("method"), r.get("n"), r.get("r"))
        cert = json.dumps(r.get("certificate_data"), sort_keys=True) if r.get("certificate_data") is not None else ""
        out.setdefault(k, []).append((r["verdict"], r.get("expected"), r.get("digest"), hashlib.md5((str(r.get("certificate")) + cert).encode()).hexdigest()[:8], "; ".join(r.get("reductions") or [])[:100]))
    return out
a, b = load(sys.argv[1]), load(sys.argv[2])
nd = 0
for k in sorted(set(a) | set(b), key=str):
    va, vb = a.get(k), b.get(k)
    line = f"{k}: {[v[:2] for v in va] if va else None}"
    if va != vb:
        nd += 1
        print("DIFF", k); print("   j1", va); print("   j2", vb)
print(f"{len(a)} keys j1, {len(b)} keys j2, {nd} differ")
from collections import Counter
print("j1 verdicts", Counter(v[0][0] + ("" if v[0][1] else "(unexp)") for v in a.values()))
