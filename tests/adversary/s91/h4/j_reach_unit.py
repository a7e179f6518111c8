# ruff: noqa
"""Unit-level probes of claims._reach/_intact with toy functions registered through the tests' door
(_mark_reviewed): which in-place changes of what a function computes with are NOT seen.  No catalog function
reaches such a value today (M findings, for the next catalog helper that does)."""
import functools, sys, types
import numpy as np
import stiefelsym
from stiefelsym.claims import Claim, _mark_reviewed, reviewed_functions

mod = types.ModuleType("stiefelsym.proofs.zz_probe"); sys.modules[mod.__name__] = mod


def probe(name, src, change):
    g = mod.__dict__
    exec(src, g)
    f = g["f"]
    c = _mark_reviewed(Claim(id="probe-%d" % len(name)+ "-" + str(abs(hash(name)) % 10**6), paper=("cond_XP",), kind="id", section="t", func=f,
                             sizes=stiefelsym.admissible(3), equivariance="x"))
    assert reviewed_functions(c) == (f,)
    change(g)
    print(f"{name:38s} change seen by _intact: {reviewed_functions(c) != (f,)}")


probe("dict->list->list (depth 3)", "T = {'a': [[1]]}\ndef f(s): return T['a'][0][0]",
      lambda g: g["T"]["a"][0].__setitem__(0, 2))
probe("numpy array in place", "W = __import__('numpy').zeros(3)\ndef f(s): return W[0]",
      lambda g: g["W"].__setitem__(0, 5.0))
probe("lru_cache helper's __wrapped__ code", "import functools\n@functools.lru_cache(None)\ndef h(n): return n\ndef f(s): return h(1)",
      lambda g: setattr(g["h"].__wrapped__, "__code__", (lambda n: n + 1).__code__))
probe("function __dict__ read by f", "def h(): pass\nh.k = 1\ndef f(s): return h.k",
      lambda g: setattr(g["h"], "k", 2))
probe("module global shadowing a builtin", "def f(s): return len([1])",
      lambda g: g.__setitem__("len", lambda x: 7))
probe("module __builtins__ (inner def)", "def f(s):\n    def inner(): return len([1])\n    return inner()",
      lambda g: g.__setitem__("__builtins__", dict(vars(__import__('builtins')), len=lambda x: 7)))
probe("class data attribute", "class K:\n    c = [1]\n    def m(self): return K.c[0]\ndef f(s): return K().m()",
      lambda g: setattr(g["K"], "c", [2]))
probe("getattr with computed name", "def h(): return 1\ndef f(s): return getattr(__import__(__name__), 'h' + '')()",
      lambda g: g.__setitem__("h", lambda: 2))
probe("engine function's code (stiefelsym.comm)", "from stiefelsym import comm\ndef f(s): return comm(s, s)",
      lambda g: setattr(g["comm"], "__code__", (lambda *a, **k: 0).__code__))
