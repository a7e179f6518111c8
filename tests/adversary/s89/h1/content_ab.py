"""A/B of the exact products' content step on s89h1-cay-inverse at (4,2): CONTENT_TERMS as shipped vs disabled."""
import sys
import time
import stiefelsym
from stiefelsym.backends import polyfield
if sys.argv[1] == "off":
    polyfield.CONTENT_TERMS = 10**18
t = time.time()
res = stiefelsym.verify(["s89h1-cay-inverse"], files=["/tmp/s89h1/out/t_poly3.py"], sizes=[(4, 2)], methods="exact",
                        timeout=250)
for r in res:
    print(sys.argv[1], r.verdict, round(time.time() - t, 1), (r.message or "")[:120])
