"""s72 review2 (attempt S7): as tmp_state_select.py, with a module global instead of a file in /tmp: in the second
phase one child imports the file once per size and traces every claim that needs that size, so rw2-glob-b sees
the global that rw2-glob-a set when both are traced there."""
from stiefelsym import admissible, claim

SEEN = set()


@claim("rw2-glob-a", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1))
def glob_a(s):
    """X^T X = I_r (true); records its size in a module global."""
    SEEN.add(int(s.n))
    return {"id": s.X.T @ s.X - s.identity(s.r)}


@claim("rw2-glob-b", kind="id", paper="No", section="t", sizes=admissible(n_min=3, r_max=1))
def glob_b(s):
    """X^T X = I_r (true) if rw2-glob-a was traced at this size in this process, else X X^T = I_n (false)."""
    if int(s.n) in SEEN:
        return {"id": s.X.T @ s.X - s.identity(s.r)}
    return {"id": s.X @ s.X.T - s.identity(s.n)}
