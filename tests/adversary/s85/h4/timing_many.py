"""Timing only: 20 claims of one true function (Xᵀ X − I_r, TRUE), 41 jobs of the tracing interpreter (the listing,
each claim's metadata and its trace with symbolic sizes).  Every verdict should be proved/checked."""
from stiefelsym import admissible, claim


def f(s):
    return {"x": s.X.T @ s.X - s.Ir}


for i in range(20):
    claim(f"many-{i}", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))(f)
