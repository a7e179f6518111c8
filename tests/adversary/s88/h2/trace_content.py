# ruff: noqa: E701, E702, E731, E741
"""Run claims with the exact method, logging each call of polyfield._content/_common_part/_dot_content
(the common-factor step of commit c0aecb37/21581d9f) with its time.  usage: trace_content.py FILE ID n,r"""
import sys
import time
import os
from stiefelsym.backends import polyfield as pf
import stiefelsym
LOG = open(os.environ.get("TRACE_LOG", "/tmp/s88h2/out/logs/content_trace.txt"), "a", buffering=1)
def wrap(name):
    f = getattr(pf, name, None)
    if f is None:
        return
    def g(*a, **k):
        if name in ('_content', '_common_part'):
            LOG.write(f'{sys.argv[2]} {sys.argv[3]} START {name}' + (f' g terms={len(a[0])} x terms={len(a[1])}' if name == '_common_part' else '') + '\n')
        t = time.perf_counter(); out = f(*a, **k); dt = time.perf_counter() - t
        extra = ""
        if name == "_content":
            extra = "None" if out is None else f"g terms={len(out[0])}"
        if name == "_dot_content":
            extra = f"shape {a[0].shape}x{a[1].shape}"
        if name == "_content" or dt > 0.05 or name == "_common_part":
            LOG.write(f"{sys.argv[2]} {sys.argv[3]} {name} {dt:.3f}s {extra}\n")
        return out
    setattr(pf, name, g)
for n in ("_content", "_common_part", "_dot_content", "_dot"):
    wrap(n)
file, cid, size = sys.argv[1], sys.argv[2], sys.argv[3]
t = time.perf_counter()
res = stiefelsym.verify([cid], files=[file], sizes=[size], methods=[os.environ.get("M", "exact")], seed=1, timeout=600)
for r in res:
    print(cid, size, r.verdict, f"{r.seconds:.2f}s", f"wall {time.perf_counter()-t:.1f}s", (r.message or "")[:200])
