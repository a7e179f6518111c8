# ruff: noqa
"""A claim of one's own under the id of a catalog Count erratum (neumann2-h-size, whose template reads the
check's detail for the hand witness): the Count's meaning quotes a number pair itself, "9 (claimed: 9)",
which the first regex match of `count_values` takes for the computed and the stated value."""
from stiefelsym import Count, admissible, claim


@claim("neumann2-h-size", kind="dim", sizes=admissible(n_max=3, r_in=(2,)))
def shadow(s):
    """A count that fails: 4 against 5."""
    return {"size of h = Psi(X0, P0) = size of v": Count(4, 5, meaning="the numbers 9 (claimed: 9) agree")}
