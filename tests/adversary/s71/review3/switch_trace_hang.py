# ruff: noqa
"""A claim that is a count at its smallest stated sizes and loops for ever while traced at a large size; a claim
whose count at a large size is a number of 10^8 digits.
Run: stiefelsym verify --claims switch_trace_hang.py --size 50,2 --method auto --jobs 1 --no-report --timeout 60"""
from stiefelsym import Count, admissible, claim

SIZES = admissible(n_max=4)


@claim("r3-trace-hang", kind="dim", sizes=SIZES)
def trace_hang(s):
    """n = n (true), but the trace at n > 4 does not end."""
    n = int(s.n)
    if n > 4:
        while True:
            pass
    return {"c": Count(n, n)}


@claim("r3-count-huge", kind="dim", sizes=SIZES)
def count_huge(s):
    """k = k (true) with k = 7^(n·10^6): about 4·10^7 digits at n = 50."""
    k = 7 ** (int(s.n) * 10 ** 6)
    return {"c": Count(k, k)}


@claim("r3-count-huge-false", kind="dim", sizes=SIZES)
def count_huge_false(s):
    """k = k + 1 (false) with k = 7^(n·10^6)."""
    k = 7 ** (int(s.n) * 10 ** 6)
    return {"c": Count(k, k + 1)}
