"""The natural notebook order: load my claims file in-process, then the catalog, then verify a catalog claim."""
import stiefelsym
stiefelsym.load_claims_file("evil_det.py")
cat = stiefelsym.load_catalog()
for meth in ("exact", "modular", "auto"):
    for r in stiefelsym.verify([cat.get("neum-gras")], sizes=[(3, 2), (4, 2)], methods=[meth], jobs=1):
        print(f"{r.claim} ({r.n},{r.r}) {r.method}: {r.verdict} -- {(r.message or r.residual or '')[:140]}")
