"""In-process API: the catalog module's helper replaced (monkeypatch); the reviewed function's identity is kept.
(neum-gras) then reads its right-hand side plus X[n,1] in every Plücker coordinate: the residual is -X[n,1], which
vanishes at X = X0 (r < n) and nowhere else generically: FALSE."""
import sys
import stiefelsym
from stiefelsym.proofs import sec7_grassmannians as m

cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
orig = m.neum_gras_rhs
m.neum_gras_rhs = lambda s, X, Xdot: [o + X[X.shape[0] - 1, 0] for o in orig(s, X, Xdot)]
for meth in (sys.argv[1] if len(sys.argv) > 1 else "exact,modular").split(","):
    for r in stiefelsym.verify([c], sizes=[(3, 2)], methods=[meth], jobs=1):
        print(f"{r.claim} ({r.n},{r.r}) {r.method}: {r.verdict} -- {(r.message or r.residual or '')[:160]} | {str(r.reductions)[:100]}")
