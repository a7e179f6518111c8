"""A false claim that the dimension-free method proves for all n, r.

The claim reads the value of its size through the public attribute ``s.n._size``
(no refusal) and behaves like the symbolic trace at the two sizes the free
method compares (its first size and its first size with n >= 3), but differently at n = 4."""
from stiefelsym import admissible, claim


@claim("adv-size-branch", paper="prep", kind="id", section="t", sizes=admissible(n_max=5))
def size_branch(s):
    """XᵀX = I at every n except n = 4, where it states X = 0 (false)."""
    if s.n._size.value == 4:
        return {"X": s.X}
    return {"XtX - I": s.X.T @ s.X - s.Ir}
