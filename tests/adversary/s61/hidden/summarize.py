"""Summarize a `stiefelsym verify` log: per claim, per method block, the verdict counts and the sizes of
every verdict other than proved/checked/numeric.  Results after a claim's `free` line belong to `auto`."""
import re
import sys
import collections
for f in sys.argv[1:]:
    print("==", f)
    tab = collections.OrderedDict()
    seen_free = set()
    for line in open(f):
        if line.startswith(' ') or line.startswith('unexpected'):
            continue
        m = re.match(r'^(\S+) \((\d+),(\d+)\) (\w+): (\w+)(.*)', line)
        if m:
            cid, n, r, meth, verd, rest = m.groups()
            t = re.search(r'\(([0-9.]+)s', rest)
            block = 'auto(' + meth + ')' if cid in seen_free else meth
            tab.setdefault(cid, collections.OrderedDict()).setdefault(block, []).append(((int(n), int(r)), verd, float(t.group(1)) if t else 0))
            continue
        m = re.match(r'^(\S+) all n, r free: (\w+)', line)
        if m:
            seen_free.add(m.group(1))
            tab.setdefault(m.group(1), collections.OrderedDict())['free'] = [('all', m.group(2), 0)]
    for cid, d in tab.items():
        print(cid)
        for meth, lst in d.items():
            c = collections.Counter(v for _, v, _ in lst)
            odd = [(s, v) for s, v, _ in lst if v not in ('proved', 'checked', 'numeric')]
            slow = [(s, t) for s, _, t in lst if t > 2]
            print(f"   {meth:16s} {dict(c)}  not-passing: {odd}  slow(>2s): {slow}")
