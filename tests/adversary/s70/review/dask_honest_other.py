# ruff: noqa
"""An honest claims file with a false claim, run on the dask cluster after dask_inprocess_pickle.py was
loaded by the same run server: its verdicts come from a process whose pickle.dumps the other file replaced.
Honest verdict: s70-other-false (XXᵀ = I_n at r < n) fails at (3,2)."""
from stiefelsym import admissible, claim


@claim("s70-other-false", kind="id", sizes=admissible(n_min=3, r_min=2, n_max=3))
def other(s):
    """XXᵀ = I_n (false for r < n)."""
    return {"xxt": s.X @ s.X.T - s.In}
