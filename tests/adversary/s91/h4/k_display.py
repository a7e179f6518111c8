# ruff: noqa
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
reg = stiefelsym.load_claims_file("evil_display_file.py")
rs = stiefelsym.verify(list(reg), sizes=[(3, 2)], methods=["modular"], jobs=1)
print("r.verdict:", [r.verdict for r in rs])
print("summary():", rs.summary()[:600])
print("_repr_latex_:", rs[0]._repr_latex_()[:300])
