"""Compare `stiefelsym verify` logs with the numpy truth of indep.py.
Usage: .venv/bin/python tests/adversary/s62/hidden/compare.py LOG...   (from /work/main)
A verdict proved/checked/numeric says "the statement holds at that size", fails says "it does not";
for a kind-"not" claim the statement is "the residual is nonzero", and the same reading applies.
Results after a claim's `free` line belong to `auto` (the CLI prints auto's lines with the method it chose)."""
import collections
import contextlib
import io
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
with contextlib.redirect_stdout(io.StringIO()):
    import indep  # noqa: E402

TRUTH = {}
for name, vals in indep.res.items():
    per = {}
    for sz, v in vals:
        per[sz] = max(per.get(sz, 0.0), v)
    for sz, v in per.items():
        TRUTH[(name, sz)] = (v > indep.TOL) if name in indep.NOT_CLAIMS else (v < indep.TOL)

PASS = {"proved", "checked", "numeric"}
for f in sys.argv[1:]:
    print("==", f)
    tab = collections.OrderedDict()
    seen_free = set()
    for line in open(f):
        if line.startswith(" "):
            continue
        m = re.match(r"^(\S+) \((\d+),(\d+)\) (\w+): (\w+)(.*)", line)
        if m:
            cid, n, r, meth, verd, rest = m.groups()
            t = re.search(r"\(([0-9.]+)s", rest)
            block = "auto" if cid in seen_free else meth
            tab.setdefault(cid, collections.OrderedDict()).setdefault(block, []).append(
                ((int(n), int(r)), verd, float(t.group(1)) if t else 0.0))
            continue
        m = re.match(r"^(\S+) all n, r free: (\w+)", line)
        if m:
            seen_free.add(m.group(1))
            tab.setdefault(m.group(1), collections.OrderedDict())["free"] = [("all", m.group(2), 0.0)]
    wrong_total = 0
    for cid, d in tab.items():
        print(cid)
        for meth, lst in d.items():
            c = collections.Counter(v for _, v, _ in lst)
            wrong, nodec = [], []
            for sz, v, _ in lst:
                if sz == "all":
                    truth = all(t for (k, _), t in TRUTH.items() if k == cid)
                else:
                    truth = TRUTH.get((cid, sz))
                if v in PASS and truth is False or v == "fails" and truth is True:
                    wrong.append((sz, v))
                elif v not in PASS and v != "fails":
                    nodec.append((sz, v))
            wrong_total += len(wrong)
            slow = [(s, t) for s, _, t in lst if t > 2]
            print(f"   {meth:8s} {dict(c)}  WRONG: {wrong or '-'}  no-decision: {nodec or '-'}  >2s: {slow or '-'}")
    print("wrong verdicts:", wrong_total)
