# ruff: noqa
"""Jupyter-like rendering of Result / ResultList objects (step 2)."""
import stiefelsym
res = stiefelsym.verify(["v64-dual-I2", "w64-dual-I2"], files=["claims.py", "negatives.py"],
                        sizes=[(3, 2)], methods=["exact", "modular", "float"], jobs=1)
print("=== ResultList._repr_markdown_()"); print(res._repr_markdown_())
print("=== ResultList._repr_latex_()"); print(res._repr_latex_())
for r in res:
    print(f"=== Result {r.claim} {r.method}: _repr_markdown_()"); print(r._repr_markdown_())
    print(f"=== Result {r.claim} {r.method}: _repr_latex_()"); print(r._repr_latex_())
    if r.verdict == "fails":
        print("residual_sympy:", repr(r.residual_sympy())[:400]); print("rerun:", r.rerun); print("witness keys:", list((r.witness or {}).keys()))
print("=== attrs", [a for a in dir(res[0]) if not a.startswith("__")])
