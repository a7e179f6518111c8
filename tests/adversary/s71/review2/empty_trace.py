# ruff: noqa
"""n = r: a trace of the empty (n − r) × (n − r) block, run twice in one process: the first exact run proves, the
second (the cached straight-line program) is an error (IndexError in ir/straightline.py, `len(M[0])`); auto after exact
likewise.  Run: .venv/bin/python tests/adversary/s71/review2/empty_trace.py"""
from stiefelsym import admissible, block
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one
cases = {
 "t-gram-plus-I (true at n=r)": lambda s: {"x": s.generic("P2","n-r","r").T @ s.generic("P2","n-r","r") + s.Ir - s.Ir},
 "f-gram-plus-I (false: = I_r)": lambda s: {"x": s.generic("P2","n-r","r").T @ s.generic("P2","n-r","r") - s.Ir},
 "t-trS+1-1": lambda s: {"x": s.tr(s.generic("S","n-r","n-r","sym")) + s.tr(s.Ir) - s.tr(s.Ir)},
 "f-trS+1": lambda s: {"x": s.tr(s.generic("S","n-r","n-r","sym")) + 1},
 "f-trGtG-trI": lambda s: {"x": s.tr(s.generic("P2","n-r","r") @ s.generic("P2","n-r","r").T) - s.tr(s.Ir)},
 "t-block": lambda s: {"x": block([[s.Ir],[s.generic("P2","n-r","r")]]).T @ block([[s.Ir],[s.generic("P2","n-r","r")]]) - s.Ir - s.generic("P2","n-r","r").T @ s.generic("P2","n-r","r")},
}
for name, fn in cases.items():
    c = Claim(id="t", paper=("prep",), kind="id", section="t", func=fn, sizes=admissible(4))
    out = []
    for m in ("exact", "exact", "modular", "modular", "float", "auto", "rational", "ball"):
        out.append(m[:3] + ":" + run_one(c, Size(3, 3), m, seed=0).verdict)
    print(name, " ".join(out))
