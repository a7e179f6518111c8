"""In-process Python API: a reviewed catalog claim's stated reason of equivariance bought for a function of one's own.
The function: the bottom row of X vanishes, X[2, :] = 0 at (3, 2) -- TRUE at X = X0 = (E1 E2), FALSE on T*V (numpy).
Route a: dataclasses.replace(catalog claim 'neum-gras', func=mine) (Claim is public, frozen: replace is the way).
Route b: @c.correction("mine") on the catalog's 'ym-monopole' (an erratum, so its corrections run), the public
decorator; the function is then a registered correction, which _reviewed_function accepts."""
import dataclasses
import sys
import stiefelsym


def bottom_row(s):
    """FALSE: the last row of X vanishes."""
    return {"x": s.X[2:3, :]}


def bottom_row_p(s):
    """FALSE: the last row of X and of P vanish."""
    return {"x": s.X[2:3, :], "p": s.P[2:3, :]}


cat = stiefelsym.load_catalog()
route = sys.argv[1]
methods = sys.argv[2].split(",")
if route == "a":
    base = cat.get("neum-gras")
    c = dataclasses.replace(base, func=bottom_row)
    print("reviewed:", c.reviewed, "equivariance:", c.equivariance[:60])
    claims = [c]
elif route == "a0":       # control: the same function in a claim of one's own
    from stiefelsym import admissible, claim
    c = claim("mine-bottom", kind="id", sizes=admissible(n_max=3))(bottom_row).claim
    claims = [c]
else:
    c = cat.get("ym-monopole")
    c.correction("mine: the last rows vanish")(bottom_row_p)
    c.correction("mine: the last row of X vanishes")(bottom_row)
    claims = [c]
for m in methods:
    res = stiefelsym.verify(claims, sizes=[(3, 2)], methods=[m], jobs=1)
    for r in res:
        print(f"{r.claim} [{r.variant}] ({r.n},{r.r}) {r.method}: {r.verdict} -- {(r.message or r.residual or '')[:150]}"
              f" | reductions: {str(r.reductions)[:200]}")
