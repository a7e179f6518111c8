# ruff: noqa: E702, E402 - a diagnosis script kept as the helper wrote it
# diagnosis of M1 (run in h3's own process; edits nothing on disk): is the coefficient cap what stops the bound?
import time
import stiefelsym
from stiefelsym.methods import fixed_size as fs
orig = fs._coefficient_rank_bound
def spy(polys):
    if polys:
        lines = polys
        spots = set()
        for line in lines:
            for j, p in enumerate(line):
                if p != 0:
                    for e in p.monoms():
                        spots.add((j, e))
        print(f"[spy] rows={len(lines)} cols={len(lines[0])} spots={len(spots)} rows*spots={len(lines)*len(spots)} cap={fs.COEFFICIENT_BOUND_ENTRIES}", flush=True)
    t = time.time(); out = orig(polys); print(f"[spy] bound={out and out[0]} in {time.time()-t:.1f}s", flush=True)
    return out
fs._coefficient_rank_bound = spy
import sys
fs.COEFFICIENT_BOUND_ENTRIES = int(sys.argv[1])
res = stiefelsym.verify(["h3-orbit-rank-twin"], files=["tests/adversary/s83/h3/hidden/sec2_hidden.py"], sizes=[(4, 3)], methods=["exact"], timeout=120)
for r in res:
    print(r.verdict, (getattr(r, "certificate", "") or getattr(r, "message", ""))[:300])
