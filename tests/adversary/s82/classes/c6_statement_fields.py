"""Class 6/2 (introspection of frozen statements): fields of a Rank or Count rewritten after construction with
object.__setattr__ (plain Python, no private name), past the dataclass's own checks.

M = XXᵀ, rank r at every point and generically (r < n at (3,2)).
 sf-any-false:    Rank(M, r + 1) whose expected is then replaced by an object equal to everything and greater than
                  nothing (__eq__ True, __gt__/__lt__ False, __index__ = r + 1): FALSE (rank r ≠ r + 1).
 sf-float-false:  expected replaced by float(r) + 0.5 ... FALSE.
 sf-bool-false:   Rank(M, r, generic=True, kernel=I − XXᵀ) with generic then set to False (a kernel on an every-point
                  rank): the statement is "rank r at every point": TRUE; the twin with expected r − 1 ... FALSE.
 sf-count-false:  Count(3, 4) with value replaced by the everything-equal object: FALSE (3 ≠ 4).
 sf-count-np:     Count(3, 4) with value replaced by numpy.int64(4): the statement is then 4 = 4 (the claim's own
                  count): TRUE as written, no hole either way; recorded to see what the engine takes.
"""
import numpy as np

from stiefelsym import Count, Rank, admissible, claim

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


class _Any(int):
    pass


class Everything:
    def __init__(self, k):
        self.k = k

    def __eq__(self, o):
        return True

    def __ne__(self, o):
        return False

    def __gt__(self, o):
        return False

    def __lt__(self, o):
        return False

    def __ge__(self, o):
        return True

    def __le__(self, o):
        return True

    def __hash__(self):
        return 0

    def __index__(self):
        return self.k

    def __int__(self):
        return self.k


@claim("sf-any-false", kind="dim", sizes=SZ)
def any_false(s):
    R = Rank(s.X @ s.X.T, int(s.r) + 1)
    object.__setattr__(R, "expected", Everything(int(s.r) + 1))
    return {"rank": R}


@claim("sf-float-false", kind="dim", sizes=SZ)
def float_false(s):
    R = Rank(s.X @ s.X.T, int(s.r) + 1)
    object.__setattr__(R, "expected", float(int(s.r)) + 0.5)
    return {"rank": R}


@claim("sf-bool-true", kind="dim", sizes=SZ)
def bool_true(s):
    R = Rank(s.X @ s.X.T, int(s.r), kernel=s.In - s.X @ s.X.T)
    object.__setattr__(R, "generic", False)
    return {"rank": R}


@claim("sf-bool-false", kind="dim", sizes=SZ)
def bool_false(s):
    R = Rank(s.X @ s.X.T, int(s.r) - 1, kernel=s.In - s.X @ s.X.T)
    object.__setattr__(R, "generic", False)
    return {"rank": R}


@claim("sf-count-false", kind="dim", sizes=SZ)
def count_false(s):
    C = Count(3, 4)
    object.__setattr__(C, "value", Everything(3))
    return {"c": C}


@claim("sf-count-np", kind="dim", sizes=SZ)
def count_np(s):
    C = Count(3, 4)
    object.__setattr__(C, "value", np.int64(4))
    return {"c": C}
