"""Class 5 (a bound's error model): the degree bound of a rank's minors where the entries' numerators are
constants and the degree sits in their denominators.  M = [[1, 1], [1, x^(-N)]], x = tr(PᵀP) (a generic
nonzero scalar on T*V): det M = x^(-N) − 1 = (1 − x^N)/x^N, whose numerator has degree 2N (x has degree 2 in the
chart's parameters) although every entry's numerator is a constant.  Generic rank 2.

md-rank2-t:  Rank(M, 2)  TRUE  (full)
md-rank1-f:  Rank(M, 1)  FALSE (rank 2; rank 1 only where x^N = 1)
md-small-f:  N = 5: Rank(M, 1) FALSE -- the bound printed by modular shows whether the minors' degree counts the
             denominators (a bound of degree 0 or 1 would be an under-estimate: the numerator has degree 10)
md-res-f:    the residual x^(-N) − 1 (FALSE), N = 5: the printed residual bound (degree 10 expected)
"""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)


def _m(s, N):
    x = s.tr(s.P.T @ s.P)
    return s.mat([[1, 1], [1, 1 / x ** N]])


@claim("md-rank2-t", kind="dim", sizes=SZ)
def md_rank2_t(s):
    return {"rank": Rank(_m(s, 5), 2)}


@claim("md-rank1-f", kind="dim", sizes=SZ)
def md_rank1_f(s):
    return {"rank": Rank(_m(s, 2**20), 1)}


@claim("md-small-f", kind="dim", sizes=SZ)
def md_small_f(s):
    return {"rank": Rank(_m(s, 5), 1)}


@claim("md-res-f", kind="id", sizes=SZ)
def md_res_f(s):
    x = s.tr(s.P.T @ s.P)
    return {"x": 1 / x ** 5 - 1}


@claim("md-low-t", kind="dim", sizes=SZ)
def md_low_t(s):
    """[[1, x⁻⁵], [x⁵, 1]]: det = 1 − x⁻⁵x⁵ = 0: rank 1 TRUE; its 2-minor's numerator has structural degree 20
    (x⁵·x⁵ over x⁵ ... ): the printed bound shows how denominators are counted."""
    x = s.tr(s.P.T @ s.P)
    return {"rank": Rank(s.mat([[1, 1 / x ** 5], [x ** 5, 1]]), 1)}


@claim("md-low-den", kind="dim", sizes=SZ)
def md_low_den(s):
    """[[1/x⁵, 1/y⁵], [1/x⁵, 1/y⁵]] (equal rows): rank 1 TRUE; entries' numerators are constants, the 2-minor as one
    fraction has numerator degree 0 (1/(x⁵y⁵) − 1/(x⁵y⁵)): the bound may be small, and rightly."""
    x = s.tr(s.P.T @ s.P)
    y = s.tr(s.P.T @ s.A @ s.P)
    return {"rank": Rank(s.mat([[1 / x ** 5, 1 / y ** 5], [1 / x ** 5, 1 / y ** 5]]), 1)}
