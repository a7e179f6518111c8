"""s72 review: a correction search whose one-step correction holds at n <= 4 only (attempt M1-M2).
e5(A) = 1 is false everywhere; the mutant e5(A) = 0 (the constant dropped) holds at n <= 4 (A is n x n) and fails
at n = 5 (e5(A) = a1 a2 a3 a4 a5)."""
from stiefelsym import admissible, claim, elementary


@claim("s72-e5-one", paper="No", kind="id", section="t", sizes=admissible(n_max=4, r_max=1))
def e5_one(s):
    """e5(A) = 1 (false at every n)."""
    e = elementary(s, s.A, 5)
    return {"e5 - 1": e[5] - 1}


@claim("s72-e5-zero", paper="No", kind="id", section="t", sizes=admissible(n_max=6, r_max=1))
def e5_zero(s):
    """e5(A) = 0 for every n (false from n = 5 on): the correction the search above would offer."""
    e = elementary(s, s.A, 5)
    return {"e5": e[5]}
