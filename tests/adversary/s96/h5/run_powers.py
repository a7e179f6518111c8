import sys
import time
from pathlib import Path

import stiefelsym
from stiefelsym.methods import fixed_size as fs

claims = stiefelsym.load(files=[Path(__file__).with_name("c1_powers.py")], catalog=False)
want = sys.argv[1:]
for c in claims:
    if want and c.id not in want:
        continue
    for meth in ("exact", "modular"):
        t = time.process_time()
        try:
            res = fs.run_exact(c, 2, 1, 0) if meth == "exact" else fs.run_points(c, 2, 1, "modular", 0)
            v, m = res.verdict, res.message[:160]
        except Exception as e:  # noqa: BLE001
            v, m = "EXC", repr(e)[:160]
        print(f"{c.id} {meth}: {v} {time.process_time() - t:.1f}s  {m}", flush=True)
