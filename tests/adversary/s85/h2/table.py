# ruff: noqa: E701, E702
"""Compare each verdict with the numpy truth (TRUTH below, from indep_output.txt)."""
import json
import sys
import collections

def truth(cid, n, r):
    if n is None:  # free: a statement for every n, r
        return not cid.endswith("-twin") and cid not in ("p2-coupled-metrics-differ-r1", "p2-catch-keyerror")
    if cid.endswith("-twin"):
        base = cid
        if base == "h2-jensen-multipliers-twin": return r == 1
        if base == "h2-general-multipliers-twin": return r == 1
        if base == "h2-quartic-multipliers-twin": return False
        if base == "h2-coupled-diagonal-twin": return r == 1
        if base == "h2-coupled-r2-metrics-twin": return False
        if base == "h2-pr-e-rank-twin": return False
        if base == "h2-trL3-expansion-twin": return n == 1   # expansion part fails wherever trΦ²A != 0 (n >= 2)
        if base == "h2-neumann-kappas-commute-twin": return r == n
        if base == "h2-magnetic-multipliers-twin": return False
        if base == "h2-magnetic-energy-twin": return n == 2
        if base == "h2-phi-bracket-trace-twin": return n <= 2
        if base == "h2-psi-bracket-trace-twin": return r <= 2
        if base == "h2-lax-over-lambda-twin": return n == 1
        if base == "p2-trL3-trIr-twin": return n == 1
        if base == "p2-magnetic-multipliers-entry-twin": return False
        if base == "p2-pr-e-rank-kernel-twin": return False
        if base == "h2-rn-velocity-twin": return n == 1
        if base == "h2-rn-velocity-all-r-twin": return r == n
        if base == "h2-gras-lambda-twin": return r == n
        if base == "h2-gras-sphere-projector-twin": return n == 1
        if base == "p2-atpoint-multipliers-twin": return n == 1
        raise KeyError(cid)
    if cid == "p2-coupled-metrics-differ-r1": return False
    if cid == "p2-catch-keyerror": return n == 1
    return True

GOOD = {"proved", "checked", "numeric"}
BAD = {"fails"}
rows = collections.Counter(); wrong = []
for f in sys.argv[1:]:
    d = json.load(open(f))
    for x in d["results"]:
        t = truth(x["claim"], x["n"], x["r"])
        v = x["verdict"]
        rows[v] += 1
        if (t and v in BAD) or (not t and v in GOOD):
            wrong.append((f, x["claim"], x["n"], x["r"], x["method"], v, t))
        if v not in GOOD | BAD:
            print("REFUSAL", f, x["claim"], (x["n"], x["r"]), x["method"], v, "|", (x.get("message") or "")[:300])
print(dict(rows))
print("WRONG:", wrong)
