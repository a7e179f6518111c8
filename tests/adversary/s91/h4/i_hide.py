# ruff: noqa
import sys; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
reg = stiefelsym.load("evil_hide_file.py", sizes=[(3, 2)])
print("stiefelsym.load:", [c.id for c in reg if "true" in c.id or "false" in c.id])
reg2 = stiefelsym.load_claims_file("evil_hide_file.py")
print("load_claims_file:", reg2.ids())
rs = stiefelsym.verify(files=["evil_hide_file.py"], sizes=[(3, 2)], methods=["modular"], jobs=1)
print("verify(files=...):", [(r.claim, r.verdict) for r in rs])
