# ruff: noqa
"""Aggregate the verdicts of the report directories into one line per claim and method."""
import collections
import json
import sys

out = collections.defaultdict(lambda: collections.defaultdict(collections.Counter))
for d in sys.argv[1:]:
    data = json.load(open(d + "/results.json"))
    recs = data["results"] if isinstance(data, dict) else data
    for r in recs:
        out[r["claim"]][d.replace("report_", "") + ":" + r["method"]][r["verdict"]] += 1
for c in out:
    print(c, "; ".join(f"{m} " + ",".join(f"{v}{n}" for v, n in sorted(cnt.items())) for m, cnt in sorted(out[c].items())))
