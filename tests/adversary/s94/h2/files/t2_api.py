import sys
import stiefelsym
import math
F = "/tmp/s94h2/files/f3_door.py"
def tr(name, f):
    try:
        out = f()
        if hasattr(out, "__iter__"):
            out = [(r.claim, r.variant, r.method, r.n, r.r, r.verdict, (r.message or "")[:90]) for r in out]
        print("OK ", name, out)
    except Exception as e:
        print("EXC", name, type(e).__name__, str(e)[:300])
cases = sys.argv[1].split(",")
reg = stiefelsym.load(files=F, sizes=[(3, 2)])
c = {k: reg.get(k) for k in ("h2-sym", "h2-door", "h2-where", "h2-raise", "h2-corrdoor")}
for k, v in c.items():
    print(k, "symbolic" if v.func.symbolic() else "sized", v.func.sizes(), [x.func.symbolic() for x in v.corrections])
if "a" in cases:
    tr("door at traced (3,2)", lambda: stiefelsym.verify(c["h2-door"], sizes=[(3, 2)], methods="exact"))
    tr("door at (4,2) not traced", lambda: stiefelsym.verify(c["h2-door"], sizes=[(4, 2)], methods="exact"))
    tr("door default sizes", lambda: stiefelsym.verify(c["h2-door"], methods="exact"))
    tr("door free only at (4,2)", lambda: stiefelsym.verify(c["h2-door"], sizes=[(4, 2)], methods="free"))
    tr("door free+exact at (4,2)", lambda: stiefelsym.verify(c["h2-door"], sizes=[(4, 2)], methods=["free", "exact"]))
if "b" in cases:
    tr("where at (17,2)", lambda: stiefelsym.verify(c["h2-where"], sizes=[(17, 2)], methods="modular"))
    tr("where at (3,2) (not admitted)", lambda: stiefelsym.verify(c["h2-where"], sizes=[(3, 2)], methods="modular"))
    tr("raise at (4,2)", lambda: stiefelsym.verify(c["h2-raise"], sizes=[(4, 2)], methods="modular"))
    tr("raise at (3,2)", lambda: stiefelsym.verify(c["h2-raise"], sizes=[(3, 2)], methods="modular"))
    tr("corrdoor at (4,2)", lambda: stiefelsym.verify(c["h2-corrdoor"], sizes=[(4, 2)], methods="exact"))
    tr("corrdoor at (3,2)", lambda: stiefelsym.verify(c["h2-corrdoor"], sizes=[(3, 2)], methods="exact"))
if "c" in cases:
    tr("files + [] claims", lambda: stiefelsym.verify([], files=F))
    tr("files + claim obj + id", lambda: stiefelsym.verify([c["h2-door"], "h2-sym"], files=F, sizes=[(4, 2)], methods="exact"))
    tr("files + claim obj + same id", lambda: stiefelsym.verify([c["h2-door"], "h2-door"], files=F, sizes=[(3, 2)], methods="exact"))
    tr("files + tuple of obj", lambda: stiefelsym.verify((c["h2-door"],), files=F, sizes=[(3, 2)], methods="exact"))
    tr("files=str empty", lambda: stiefelsym.verify(c["h2-door"], files="", sizes=[(4, 2)], methods="exact"))
    tr("generator of claims", lambda: stiefelsym.verify((x for x in [c["h2-door"]]), sizes=[(4, 2)], methods="exact"))
    tr("sizes as generator", lambda: stiefelsym.verify(c["h2-door"], sizes=((n, 2) for n in [4]), methods="exact"))
    tr("sizes str '4,2'", lambda: stiefelsym.verify(c["h2-door"], sizes=["4,2"], methods="exact"))
    tr("size (2,4)", lambda: stiefelsym.verify(c["h2-door"], sizes=[(2, 4)], methods="exact"))
if "d" in cases:
    for name, kw in [("timeout nan", dict(timeout=float("nan"))), ("timeout inf", dict(timeout=math.inf)),
                     ("timeout True", dict(timeout=True)), ("memory 1e-12", dict(memory=1e-12)),
                     ("timeout 1e-300", dict(timeout=1e-300)), ("budget 1e-300", dict(budget=1e-300)),
                     ("memory 1e6", dict(memory=1e6)), ("timeout np.float64", dict(timeout=__import__("numpy").float64(30))),
                     ("jobs True", dict(jobs=True)), ("seed True", dict(seed=True)), ("budget 0", dict(budget=0))]:
        tr(name, lambda: stiefelsym.verify(c["h2-sym"], sizes=[(3, 2)], methods="modular", **kw))
