"""Review h4, batch d: divisions in the free algebra after a970e073 (stop 82, item 3).

By hand (c a number at each size; "undefined" = a division by 0 at that size, where every fixed-size method
says error; a proof "for all n, r" there is the scope hole H1/Q of earlier rounds):
  d-npr          ((n + r) X)/(n + r) - X = 0                TRUE at every size (n + r >= 2): expected proved by free
  d-npr-false    ((n + r) X)/(n + r) - 2X = 0              FALSE everywhere
  d-2np1         ((2n + 1) X)/(2n + 1) - X = 0             TRUE (control: a divisor the door accepts)
  d-zero-prod    (X / c) * c = 0, c = 1 - 1                 undefined at every size (0/0)
  d-r2-prod      (X / c) * c = 0, c = tr(I_r) - 2, at r = 2  undefined at every size of the family
  d-r2-prod-all  the same, stated at every r                 undefined at r = 2, FALSE elsewhere (= X)
  d-mu-npr       R(n + r) (mu = n + r): A^-1 R - R A^-1 = 0   TRUE (resolvent at a positive size; the A^-1 rule
                                                               divides by mu = n + r, which the door refuses)
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4)
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def npr(s):
    return s.tr(s.In) + s.tr(s.Ir)


@claim("d-npr", kind="id", sizes=SZ)
def d_npr(s):
    return {"res": (s.X * npr(s)) / npr(s) - s.X}


@claim("d-npr-false", kind="id", sizes=SZ)
def d_npr_false(s):
    return {"res": (s.X * npr(s)) / npr(s) - 2 * s.X}


@claim("d-2np1", kind="id", sizes=SZ)
def d_2np1(s):
    c = 2 * s.tr(s.In) + 1
    return {"res": (s.X * c) / c - s.X}


@claim("d-zero-prod", kind="id", sizes=SZ)
def d_zero_prod(s):
    c = s.q(1) - s.q(1)
    return {"res": (s.X / c) * c}


@claim("d-r2-prod", kind="id", sizes=R2)
def d_r2_prod(s):
    c = s.tr(s.Ir) - 2
    return {"res": (s.X / c) * c}


@claim("d-r2-prod-all", kind="id", sizes=SZ)
def d_r2_prod_all(s):
    c = s.tr(s.Ir) - 2
    return {"res": (s.X / c) * c}
