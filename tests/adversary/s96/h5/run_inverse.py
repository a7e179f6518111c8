import sys
import time
from pathlib import Path

import stiefelsym
from stiefelsym.methods import fixed_size as fs

claims = stiefelsym.load(files=[Path(__file__).with_name("c2_inverse.py")], catalog=False)
n, r = int(sys.argv[1]), int(sys.argv[2])
for c in claims:
    for meth in ("exact", "modular"):
        t = time.process_time()
        try:
            res = fs.run_exact(c, n, r, 0) if meth == "exact" else fs.run_points(c, n, r, "modular", 0)
            v, m = res.verdict, res.message[:150]
        except Exception as e:  # noqa: BLE001
            v, m = "EXC", repr(e)[:150]
        print(f"{c.id} ({n},{r}) {meth}: {v} {time.process_time() - t:.1f}s  {m}", flush=True)
