"""Numbers of unusual types in Rank and Count statements (a rank is an integer: 3/2, 1.5, 2.0, -1)."""
from fractions import Fraction

from stiefelsym import Count, Rank, admissible, claim


@claim("s73-count-float-big", kind="dim", sizes=admissible(n_max=3))
def count_float_big(s):
    """10^17 + 1 = 10^17 written with a float value: FALSE."""
    return {"count": Count(float(10**17 + 1), 10**17)}


@claim("s73-rank-half", kind="dim", sizes=admissible(n_max=3, r_min=2))
def rank_half(s):
    """X^T X has rank 3/2: FALSE (it has rank r; no rank is 3/2)."""
    return {"rank": Rank(s.X.T @ s.X, Fraction(3, 2))}


@claim("s73-rank-float", kind="dim", sizes=admissible(n_max=3, r_min=2))
def rank_float(s):
    """X^T X has rank 1.5: FALSE."""
    return {"rank": Rank(s.X.T @ s.X, 1.5)}


@claim("s73-rank-neg", kind="dim", sizes=admissible(n_max=3))
def rank_neg(s):
    """X^T X has rank -1: FALSE."""
    return {"rank": Rank(s.X.T @ s.X, -1)}


@claim("s73-rank-generic-zero", kind="dim", sizes=admissible(n_max=3))
def rank_generic_zero(s):
    """Phi has rank 2 at every point (generic=0): FALSE (Phi = 0 at P = 0)."""
    return {"rank": Rank(s.Phi, 2, generic=0)}


@claim("s73-rank-generic-str", kind="dim", sizes=admissible(n_max=3))
def rank_generic_str(s):
    """Phi has rank 2 at every point (generic='no'): FALSE as written if read as every point; TRUE generically."""
    return {"rank": Rank(s.Phi, 2, generic="no")}


@claim("s73-count-fraction-rank", kind="dim", sizes=admissible(n_max=3))
def count_fraction(s):
    """Count(Fraction(7, 2), 3): FALSE."""
    return {"count": Count(Fraction(7, 2), 3)}
