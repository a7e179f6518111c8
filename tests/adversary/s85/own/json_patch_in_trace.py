"""Class 7: json.dumps replaced while the claim is traced (after the import's check): the answer line is written
with it.  The patched dumps rewrites the residual's constant 1/3 into 1/2 in the graph's data."""
import json
from fractions import Fraction
from stiefelsym import admissible, claim

_dumps = json.dumps


def _patched(obj, *a, **k):
    s = _dumps(obj, *a, **k)
    return s


@claim("js-f", kind="id", sizes=admissible(n_max=3))
def js_f(s):
    json.dumps = _patched
    return {"x": s.X * Fraction(1, 3) - s.X * Fraction(1, 2)}
