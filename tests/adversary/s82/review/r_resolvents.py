"""Review h4, batch r: the resolvent and A^-1 rules' door for divisors (stop 82, item 3).

R(mu) = (mu I - A)^-1, A^-1 of a generic symmetric A (metric realization: A positive definite).  By hand:
R(mu) and R(nu) commute (both rational functions of A); A^-1 R(mu) = R(mu) A^-1 likewise; the resolvent identity
(nu - mu) R(mu) R(nu) = R(mu) - R(nu) holds for any mu, nu (0 = 0 at mu = nu).
  r-ainv-npr        A^-1 R(n + r) - R(n + r) A^-1 = 0                TRUE everywhere; the A^-1 rule divides by mu =
                                                                     n + r >= 2, never 0
  r-ainv-npr-false  A^-1 R(n + r) - R(n + r) = 0                      FALSE (A^-1 R is not R)
  r-ainv-2n         A^-1 R(2n) - R(2n) A^-1 = 0                       TRUE (control: mu = 2n, one monomial)
  r-res-npr         R(l) R(l + n + r) - R(l + n + r) R(l) = 0         TRUE; the resolvent identity divides by n + r
  r-res-npr-false   R(l) R(l + n + r) - R(l)^2 = 0                    FALSE
  r-res-2n          R(l) R(l + 2n) - R(l + 2n) R(l) = 0               TRUE (control)
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def npr(s):
    return s.tr(s.In) + s.tr(s.Ir)


@claim("r-ainv-npr", kind="id", sizes=SZ, realization="metric")
def r_ainv_npr(s):
    R = s.resolvent(npr(s))
    return {"res": s.Ainv @ R - R @ s.Ainv}


@claim("r-ainv-npr-false", kind="id", sizes=SZ, realization="metric")
def r_ainv_npr_false(s):
    R = s.resolvent(npr(s))
    return {"res": s.Ainv @ R - R}


@claim("r-ainv-2n", kind="id", sizes=SZ, realization="metric")
def r_ainv_2n(s):
    R = s.resolvent(2 * s.tr(s.In))
    return {"res": s.Ainv @ R - R @ s.Ainv}


@claim("r-res-npr", kind="id", sizes=SZ)
def r_res_npr(s):
    R1, R2 = s.resolvent(s.lam), s.resolvent(s.lam + npr(s))
    return {"res": R1 @ R2 - R2 @ R1}


@claim("r-res-npr-false", kind="id", sizes=SZ)
def r_res_npr_false(s):
    R1, R2 = s.resolvent(s.lam), s.resolvent(s.lam + npr(s))
    return {"res": R1 @ R2 - R1 @ R1}


@claim("r-res-2n", kind="id", sizes=SZ)
def r_res_2n(s):
    R1, R2 = s.resolvent(s.lam), s.resolvent(s.lam + 2 * s.tr(s.In))
    return {"res": R1 @ R2 - R2 @ R1}
