# ruff: noqa
"""Defect demonstration on a COPY of the package (/tmp/s66rv/pkg, never /work/main/stiefelsym): the verifying
process imports, at replay time, a module that appeared in the package folder AFTER the claims file's
children ran and the package's digests were compared (run/userfile.py _engine_unchanged).  The graph of
c13b_named_module_spawn.py names 'stiefelsym.zz_evil.step'; seal.engine_module_of walks the package folder on disk at
that moment and replay._registered imports the new file: its code runs in the verifying process.

Run:  PYTHONPATH=/tmp/s66rv/pkg STIEFELSYM_CONFINE=spawn /work/main/.venv/bin/python e2e_lazy_import.py"""
import os, sys, pathlib
import stiefelsym
assert stiefelsym.__file__.startswith("/tmp/s66rv/pkg/"), stiefelsym.__file__
HERE = pathlib.Path(__file__).resolve().parent
pkg = pathlib.Path(stiefelsym.__file__).parent
evil = pkg / "zz_evil.py"
marker = pathlib.Path("/tmp/s66rv/evil_ran.txt")
for p in (evil, marker):
    if p.exists():
        p.unlink()

reg = stiefelsym.load([HERE / "c13b_named_module_spawn.py"])          # children run, digests compared: unchanged
print("loaded:", [c.id for c in reg], "; zz_evil in sys.modules:", "stiefelsym.zz_evil" in sys.modules)

# what a process the SPAWN child left behind (or anyone with write access) does after the comparison:
evil.write_text('''
import os, sys
T = sys.modules["stiefelsym.ir.trace"]
with open("/tmp/s66rv/evil_ran.txt", "a") as f:
    f.write(f"zz_evil imported in pid {os.getpid()} (verifying process tree of {os.getppid()})\\n")
def step(s):
    if T._ACTIVE:
        return T._ACTIVE[-1].prim("stiefelsym.zz_evil.step", (s,), {})
T._NAMED[id(step)] = ("stiefelsym.zz_evil.step", step)
Res = sys.modules["stiefelsym.results"].Result   # any code runs here, in the process that computes verdicts
def _forge(self):
    if self.claim.startswith("c13b"):
        self.verdict, self.expected, self.witness, self.message = "checked", True, None, ""
_orig_reduce = Res.__reduce_ex__
def _reduce_ex(self, proto):
    _forge(self)
    return _orig_reduce(self, proto)
Res.__reduce_ex__ = _reduce_ex
''')
res = stiefelsym.verify(list(reg), methods=["modular"], sizes=[(3, 2)], jobs=1)
for r in res:
    print(r.claim, r.n, r.r, r.method, r.verdict, r.expected, (r.message or "")[:200])
print("marker:", marker.read_text() if marker.exists() else "(none: the new module was not imported)")
evil.unlink()
