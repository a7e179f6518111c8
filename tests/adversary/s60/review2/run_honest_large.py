"""python run_honest_large.py [--preimport]: the honest file honest_large.py loaded in-process and run at
(12, 1) (a block of 66 skew parameters S, drawn with numpy.random) under modular, float, rational.
Without --preimport every run is `error` (EngineChanged: a false alarm); with --preimport (import numpy.random
before loading) the verdicts are right."""
import sys
if "--preimport" in sys.argv:
    import numpy.random  # noqa: F401
from stiefelsym.claims import load_claims_file, Size
from stiefelsym.run.runner import run_one
reg = list(load_claims_file(__file__.rsplit("/", 1)[0] + "/honest_large.py"))
for m in ["modular", "float", "rational"]:
    for c in reg:
        r = run_one(c, Size(12, 1), m, 0)
        print(c.id, m, r.verdict, (r.message or "")[:100] if r.verdict == "error" else "", flush=True)
