import stiefelsym
stiefelsym.load_claims_file("evil_path.py")
cat = stiefelsym.load_catalog()
print("in the catalog:", "zz-bottom-row" in [c.id for c in cat])
for r in [] if "zz-bottom-row" not in [c.id for c in cat] else stiefelsym.verify(["zz-bottom-row"], methods=["exact", "modular", "auto"], jobs=1):
    print(r.claim, r.n, r.r, r.method, r.verdict, r.traced[:1], str(r.reductions)[:90])
