"""s72 review2: honest true claims used as the base of forged results files (attempts C*)."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=4)


@claim("rw2-xtx", kind="id", paper="No", section="t", sizes=SIZES)
def xtx(s):
    """X^T X X^T X = I_r (true on V)."""
    return {"id": s.X.T @ s.X @ s.X.T @ s.X - s.identity(s.r)}


@claim("rw2-false", kind="id", paper="No", section="t", sizes=SIZES)
def false_one(s):
    """X X^T = I_n (false for r < n)."""
    return {"id": s.X @ s.X.T - s.identity(s.n)}
