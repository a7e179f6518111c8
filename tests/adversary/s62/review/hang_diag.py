"""Diagnosis of the hang of zh-h-false: _Sides._single of stiefelsym/ir/passes.py follows single-part sides
forever (a side whose one part leads back to itself).  Wraps _single to detect the cycle (no engine file edited)."""
import sys
from pathlib import Path
from stiefelsym.ir import passes
from stiefelsym.claims import load_claims_file, Size
from stiefelsym.run.runner import run_one


def single(self, x):
    x = self.find(x)
    seen = []
    while len(self.parts[x]) == 1:
        if x in seen:
            raise RuntimeError(f"cycle of single-part sides: {seen + [x]} (atoms {[self.atom[i] for i in seen]})")
        seen.append(x)
        x = self.find(self.parts[x][0])
    return x


passes._Sides._single = single
claims = {c.id: c for c in load_claims_file(Path(__file__).with_name("zeros_hang.py"))}
res = run_one(claims[sys.argv[1]], Size(3, 2), "modular", 0)
print(res.verdict, res.message[:400])
