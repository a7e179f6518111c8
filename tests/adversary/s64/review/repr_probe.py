# ruff: noqa
"""Jupyter displays of results and claims with hostile titles (r64); run with the venv's python."""
import stiefelsym
res = stiefelsym.verify(files=["tex_verdict.py", "md_inject.py"], methods=["modular"])
print(res._repr_markdown_()[-1500:])
print(res._repr_latex_())
for r in res:
    r._repr_markdown_(); r._repr_latex_()
reg = stiefelsym.load("tex_verdict.py")
for c in reg:
    print(c._repr_latex_())
