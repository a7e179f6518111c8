"""Run the claims through the Python API (stiefelsym.verify / stiefelsym.load)."""
import time
import stiefelsym

HERE = __file__.rsplit("/", 1)[0]
t0 = time.time()
res = stiefelsym.verify(files=f"{HERE}/claims.py", methods=["exact", "modular", "float", "free"], sizes=[(3, 2), (4, 2)], jobs=1)
print("claims ok:", res.ok, "runs:", len(res), f"{time.time() - t0:.1f}s")
print(res.summary())
neg = stiefelsym.verify(files=f"{HERE}/negatives.py", methods=["exact", "modular"], sizes=[(4, 2)], jobs=1)
print("negatives ok:", neg.ok)
for r in neg:
    print(r.claim, r.n, r.r, r.method, r.verdict, r.expected)
f = [r for r in neg if r.verdict == "fails" and r.method == "exact" and r.claim == "u2-neg-sign"][0]
print("rerun:", f.rerun)
print("witness keys:", sorted(f.witness) if isinstance(f.witness, dict) else type(f.witness))
print("residual_sympy:", str(f.residual_sympy())[:200])
print("markdown head:", f._repr_markdown_()[:300].replace("\n", " | "))
print("latex head:", neg._repr_latex_()[:200].replace("\n", " "))
reg = stiefelsym.load(f"{HERE}/claims.py")
print("load ->", type(reg), [c for c in reg][:3] if hasattr(reg, "__iter__") else reg)
