# ruff: noqa
"""Ranks at every point and generic, with expected ranks given as sizes (s.r) and hostile numbers."""
from stiefelsym import Rank, Count, admissible, claim


@claim("rk-PPt-every", kind="dim", sizes=admissible(n_max=4))
def rk_ppt_every(s):
    """rank P P^T = r at every point (false: P = 0 is a point of T*V)."""
    return {"rank": Rank(s.P @ s.P.T, s.r, generic=False)}


@claim("rk-PPt-generic", kind="dim", sizes=admissible(n_max=4))
def rk_ppt_generic(s):
    """generic rank P P^T = r (true for r < n; at r = n too)."""
    return {"rank": Rank(s.P @ s.P.T, s.r)}


@claim("rk-XplusP-every", kind="dim", sizes=admissible(n_max=4))
def rk_xplusp_every(s):
    """rank (X + P) = r at every point (true: (X+P)^T (X+P) = I + P^T P)."""
    return {"rank": Rank(s.X + s.P, s.r, generic=False)}


@claim("rk-XPsum-every", kind="dim", sizes=admissible(n_max=4, n_min=2))
def rk_xpsum_every(s):
    """rank (X X^T + P P^T) = r at every point (false where 2r <= n generically, and at r = n... rank n = r: true)."""
    return {"rank": Rank(s.X @ s.X.T + s.P @ s.P.T, s.r, generic=False)}


@claim("rk-neg", kind="dim", sizes=admissible(n_max=3))
def rk_neg(s):
    """rank X = -1 (false)."""
    return {"rank": Rank(s.X, -1)}


@claim("rk-huge", kind="dim", sizes=admissible(n_max=3))
def rk_huge(s):
    """rank X = 2^80 (false)."""
    return {"rank": Rank(s.X, 2 ** 80)}


@claim("rk-zero-empty", kind="dim", sizes=admissible(n_max=3))
def rk_zero(s):
    """rank of the zero matrix = 0 at every point (true)."""
    return {"rank": Rank(s.X - s.X, 0, generic=False)}


@claim("ct-big", kind="dim", sizes=admissible(n_max=3))
def ct_big(s):
    """Count 2^4000 = 2^4000 + 1 (false)."""
    return {"c": Count(2 ** 4000, 2 ** 4000 + 1)}


@claim("ct-big-true", kind="dim", sizes=admissible(n_max=3))
def ct_big_true(s):
    """Count 10^5000 = 10^5000 (true, a number past Python's int-to-str limit)."""
    return {"c": Count(10 ** 5000, 10 ** 5000)}
