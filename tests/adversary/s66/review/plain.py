# ruff: noqa
from stiefelsym import admissible, claim, comm

@claim("rv-plain", kind="id", sizes=admissible(n_max=3))
def plain(s):
    X = s.X
    return {"sym": X @ X.T - (X @ X.T).T}
