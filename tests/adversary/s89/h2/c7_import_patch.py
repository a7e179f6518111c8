# ruff: noqa: E402
"""s89h2 class 7: patches made when the file is imported (module level), in the process that traces it.
 c7i-numpy (FALSE): numpy.matmul and numpy.ndarray-free patch: numpy.linalg.norm replaced by a function returning 0,
    fractions.Fraction.__add__ left alone; the claim XXᵀ = I_n (r < n) must still fail.
"""
import numpy
numpy.linalg.norm = lambda *a, **k: 0.0
numpy.isfinite = lambda x: True
from stiefelsym import admissible, claim

@claim("c7i-numpy", kind="id", sizes=admissible(n_max=3, n_min=2, where=lambda n, r: r < n))
def a(s):
    """FALSE: XXᵀ = I_n."""
    return {"r": s.X @ s.X.T - s.In}
