"""W1 (minimal): a reviewed catalog claim's function object kept, its code replaced (in-process Python API).
The statement verified: the last row of X vanishes at (3,2) -- FALSE on T*V (true at X = X0 only)."""
import stiefelsym

def bottom_row(s):
    return {"x": s.X[2:3, :]}

c = stiefelsym.load_catalog().get("neum-gras")
c.func.__code__ = bottom_row.__code__          # identity kept: claims.reviewed_functions(c) still holds c.func
for r in stiefelsym.verify([c], sizes=[(3, 2)], methods=["exact", "modular"], jobs=1):
    print(r.method, r.verdict, r.traced, r.reductions[:1])
