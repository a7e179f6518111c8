"""Counts built from sizes (class 3/1: what the free method makes of a size's arithmetic).

 cnt-sq-false:    Count(n·n, n + n): FALSE at n = 3 (9 ≠ 6; equal at n = 2 only).
 cnt-sq-true:     Count(n·n − n, n·(n − 1)): TRUE.
 cnt-floor-false: Count(((n·r) // 2)·2, n·r): FALSE where n·r is odd ((3,1): 2 ≠ 3).
 cnt-floor-true:  Count(((n·(n − 1)) // 2)·2, n·(n − 1)): TRUE (n(n−1) is even).
 cnt-mod-false:   Count((n·r) % 2, 0): FALSE where n·r is odd.
 cnt-neg-false:   Count((r − n) // 2, −((n − r) // 2)): FALSE where n − r is odd ((3,2): −1 ≠ 0).
 cnt-rank-false:  Count(n·r − r·(r + 1)//2, dim so(n) = n(n−1)//2): FALSE in general ((3,1): 2 ≠ 3... (3,2): 3 = 3,
                  (3,1): 3 − 1 = 2 ≠ 3).
"""
from stiefelsym import Count, admissible, claim

SZ = admissible(n_max=3)


@claim("cnt-sq-false", kind="dim", sizes=SZ)
def sq_false(s):
    return {"c": Count(s.n * s.n, s.n + s.n)}


@claim("cnt-sq-true", kind="dim", sizes=SZ)
def sq_true(s):
    return {"c": Count(s.n * s.n - s.n, s.n * (s.n - 1))}


@claim("cnt-floor-false", kind="dim", sizes=SZ)
def floor_false(s):
    return {"c": Count(((s.n * s.r) // 2) * 2, s.n * s.r)}


@claim("cnt-floor-true", kind="dim", sizes=SZ)
def floor_true(s):
    return {"c": Count(((s.n * (s.n - 1)) // 2) * 2, s.n * (s.n - 1))}


@claim("cnt-mod-false", kind="dim", sizes=SZ)
def mod_false(s):
    return {"c": Count((s.n * s.r) % 2, 0)}


@claim("cnt-neg-false", kind="dim", sizes=SZ)
def neg_false(s):
    return {"c": Count((s.r - s.n) // 2, -((s.n - s.r) // 2))}


@claim("cnt-rank-false", kind="dim", sizes=SZ)
def rank_false(s):
    return {"c": Count(s.n * s.r - s.r * (s.r + 1) // 2, s.n * (s.n - 1) // 2)}
