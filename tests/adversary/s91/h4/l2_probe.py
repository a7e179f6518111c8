# ruff: noqa
import sys, os, traceback; sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import stiefelsym
from stiefelsym.claims import reviewed_functions
cat = stiefelsym.load_catalog()
c = cat.get("neum-gras")
m = sys.modules["stiefelsym.proofs.sec7_grassmannians"]
orig = m.neum_gras_rhs
calls = [0]
def neum_gras_rhs(s, X, Xdot):
    calls[0] += 1
    st = [f.name for f in traceback.extract_stack()[-12:-2]]
    print(f"pid {os.getpid()} call {calls[0]} scene={type(s).__name__} stack={st[-6:]}", file=sys.stderr, flush=True)
    return orig(s, X, Xdot)
m.neum_gras_rhs = neum_gras_rhs
import stiefelsym.methods.fixed_size as fs
o = fs._reviewed_function
def rf(claim, func):
    print(f"pid {os.getpid()} reviewed check at calls={calls[0]}", file=sys.stderr, flush=True)
    return o(claim, func)
fs._reviewed_function = rf
for r in stiefelsym.verify([c], sizes=[(3, 2)], methods=[sys.argv[1]], jobs=1):
    print(r.method, r.verdict, r.message[:100] if r.message else "")
