"""Route A again, beyond the default sizes: the free method compares the symbolic graph with the graph
at every size the claim LISTS (admissible(n_max=5): n <= 5), but the statement admits every n, and an
explicit --size 7,2 is inside it.  The claim reads its size (s.n._size, as size_branch_free.py) and
states X = 0 at n = 7 only."""
from stiefelsym import admissible, claim


@claim("adv-size-branch-beyond", kind="id", sizes=admissible(n_max=5))
def size_branch_beyond(s):
    """X^T X = I at every n except n = 7 (beyond the listed sizes, inside the statement): X = 0 there (false)."""
    if s.n._size.value == 7:
        return {"X": s.X}
    return {"XtX - I": s.X.T @ s.X - s.Ir}
