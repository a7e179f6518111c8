"""In-process run of zh-orig (modular, 3,2) with a faulthandler dump after 15 s: where it hangs."""
import faulthandler
import sys
from pathlib import Path
from stiefelsym.claims import load_claims_file, Size
from stiefelsym.run.runner import run_one
claims = {c.id: c for c in load_claims_file(Path(__file__).with_name("zeros_hang.py"))}
faulthandler.dump_traceback_later(float(sys.argv[3]) if len(sys.argv) > 3 else 15, exit=True)
res = run_one(claims[sys.argv[1]], Size(3, 2), sys.argv[2], 0)
print(res.verdict, res.message)
