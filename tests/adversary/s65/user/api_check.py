# ruff: noqa
"""Python API and Jupyter displays on a few claims of claims_s65.py."""
import os
import time

import stiefelsym

HERE = os.path.dirname(os.path.abspath(__file__))
FILE = os.path.join(HERE, "claims_s65.py")

t0 = time.time()
res = stiefelsym.verify(["s65-psi-zero", "s65-psi-zero-twin", "s65-lambda-1-minus-1-twin", "s65-dual-count-twin",
                         "s65-grassmannian-dimension"],
                        files=FILE, sizes=[(3, 2), (4, 2)], methods=["exact", "modular", "float"], seed=3)
print("seconds", round(time.time() - t0, 2))
print("ok", res.ok)
for r in res:
    print(r.claim, r.n, r.r, r.method, r.verdict, r.expected)
print(res.summary())
fails = [r for r in res if r.verdict == "fails"]
f = fails[0]
print("FAIL0", f.claim, f.method, "witness:", f.witness, "rerun:", f.rerun)
for f in fails[:6]:
    try:
        print("residual_sympy", f.claim, f.method, repr(f.residual_sympy())[:200])
    except Exception as e:
        print("residual_sympy raised", f.claim, f.method, type(e).__name__, e)
print("---- repr(res[0])")
print(repr(res[0])[:600])
print("---- res[0]._repr_html_")
h = getattr(res[0], "_repr_html_", None)
print("has _repr_html_:", h is not None)
if h:
    print((h() or "")[:600])
print("---- res._repr_markdown_")
m = getattr(res, "_repr_markdown_", None)
print((m() if m else "NO _repr_markdown_")[:1500])
print("---- res._repr_latex_")
l = getattr(res, "_repr_latex_", None)
print((l() if l else "NO _repr_latex_")[:1500])
print("---- single failure _repr_markdown_")
print(fails[0]._repr_markdown_()[:1500])

# bad input
for bad in (dict(claims=["s65-nope"], files=FILE), dict(claims=["s65-psi-zero"], files=FILE, sizes=[(2, 3)]),
            dict(claims=["s65-od-projection"], files=FILE, sizes=[(3, 2)]), dict(files=FILE + "x")):
    try:
        stiefelsym.verify(**bad, methods="modular")
        print("no error for", bad)
    except Exception as e:
        print("bad input", bad, "->", type(e).__name__, str(e)[:300])
