# ruff: noqa
"""A count of a number of 845 099 decimal digits (7^(10^6)); Python's int -> str is quadratic (about 14 s for this
number here), so every decimal rendering of it costs that.
Run: stiefelsym verify --claims count_digits.py --size 4,2 --method auto --jobs 1 --no-report"""
from stiefelsym import Count, admissible, claim

SIZES = admissible(n_max=4)


@claim("r3-digits-true", kind="dim", sizes=SIZES)
def digits_true(s):
    """k = k with k = 7^(10^6) (true)."""
    k = 7 ** (10 ** 6)
    return {"c": Count(k, k)}
