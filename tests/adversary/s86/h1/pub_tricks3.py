"""Public-API tricks, batch 3 (dimension statements, spectra; classes 1, 3, 5).  Truths by hand:

  pc-e2-t      e_2(X X^T) - r(r-1)/2 = 0.  TRUE: X X^T is a projector of rank r (r ones, n - r zeros).
  pc-e2-f      e_2(X X^T) - r(r+1)/2 = 0.  FALSE (differs by r).
  pc-e3n-f     e_3(X X^T) = 0 at r = 3 <= n.  FALSE (e_3 = C(r,3) = 1 at r = 3).
  pc-rank-t    Rank(X X^T, r, generic=False).  TRUE (rank r projector at every point).
  pc-rank-f    Rank(X X^T + e1 e1^T, r + 1, generic=False), e1 = s.In[:, :1].  FALSE at the points where e1 is in
               the range of X (then the rank is r); TRUE at a generic point.  Right: fails or inconclusive (never proved).
  pc-grank-t   Rank(X X^T + e1 e1^T, r + 1) (generic).  TRUE (at a generic point e1 is not in range X, r < n).
  pc-count-f   Count(tr(X X^T), 3) at (3,2).  FALSE (tr X X^T = r = 2).
  pc-count-t   Count(tr(X X^T), 2) at (3,2).  TRUE.
  pc-det-t     det(X^T X) - 1 = 0.  TRUE.
  pc-det-f     det(X^T X + X^T X) - 2 = 0 at r = 2.  FALSE (det(2 I_2) = 4).
  pc-xaxrank-m Rank(X^T A X, 1, generic=False) at r = 1, standard realization (A = diag(a), a generic real): FALSE
               for an indefinite A (x^T A x = 0 on a real cone); metric realization: TRUE.  Either fails or
               inconclusive is right for the standard one; proved is wrong.
"""

from stiefelsym import Count, Rank, admissible, claim, det, elementary

SZ = admissible(n_max=4, where=lambda n, r: r < n)


@claim("pc-e2-t", kind="id", sizes=admissible(n_max=4))
def _e2t(s):
    e = elementary(s, s.X @ s.X.T, 2)
    return {"e2": e[2] - (s.tr(s.Ir) * s.tr(s.Ir) - s.tr(s.Ir)) / 2}


@claim("pc-e2-f", kind="id", sizes=admissible(n_max=4))
def _e2f(s):
    e = elementary(s, s.X @ s.X.T, 2)
    return {"e2": e[2] - (s.tr(s.Ir) * s.tr(s.Ir) + s.tr(s.Ir)) / 2}


@claim("pc-e3n-f", kind="id", sizes=admissible(n_max=4, r_min=3, r_max=3))
def _e3(s):
    return {"e3": elementary(s, s.X @ s.X.T, 3)[3]}


@claim("pc-rank-t", kind="dim", sizes=SZ)
def _rt(s):
    return {"rk": Rank(s.X @ s.X.T, int(s.r), generic=False)}


@claim("pc-rank-f", kind="dim", sizes=SZ)
def _rf(s):
    e = s.In[:, :1]
    return {"rk": Rank(s.X @ s.X.T + e @ e.T, int(s.r) + 1, generic=False)}


@claim("pc-grank-t", kind="dim", sizes=SZ)
def _grt(s):
    e = s.In[:, :1]
    return {"rk": Rank(s.X @ s.X.T + e @ e.T, int(s.r) + 1)}


@claim("pc-count-f", kind="dim", sizes=[(3, 2)])
def _cf(s):
    return {"c": Count(s.tr(s.X @ s.X.T), 3)}


@claim("pc-count-t", kind="dim", sizes=[(3, 2)])
def _ct(s):
    return {"c": Count(s.tr(s.X @ s.X.T), 2)}


@claim("pc-det-t", kind="id", sizes=admissible(n_max=4))
def _dt(s):
    return {"d": det(s, s.X.T @ s.X) - 1}


@claim("pc-det-f", kind="id", sizes=admissible(n_max=4, r_min=2, r_max=2))
def _df(s):
    return {"d": det(s, s.X.T @ s.X + s.X.T @ s.X) - 2}


@claim("pc-xaxrank-m", kind="dim", sizes=admissible(n_max=3, r_max=1, where=lambda n, r: n > 1))
def _xax(s):
    return {"rk": Rank(s.X.T @ s.A @ s.X, 1, generic=False)}


@claim("pc-xaxrank-metric", kind="dim", realization="metric",
       sizes=admissible(n_max=3, r_max=1, where=lambda n, r: n > 1))
def _xaxm(s):
    return {"rk": Rank(s.X.T @ s.A @ s.X, 1, generic=False)}
