"""Free method, families r = 1, 2 (columns E1, E2 of R^r): a division by a 1×1 word (an entry of an r×r matrix,
E1ᵀ M E2).  NCPoly._divisor_value refuses trace monomials, and scalar_value() returns the coefficient of the empty
word only: a word term of a scalar might be dropped.

Truth (by hand; numpy in truth.py): at r = 2, ψ12 = (XᵀP − PᵀX)[0,1] is a generic nonzero number.
wd-inv-f     1/(1 + ψ12) − 1 = 0                    FALSE
wd-inv-t     (1 + ψ12)·(1/(1 + ψ12)) − 1 = 0        TRUE (where 1 + ψ12 ≠ 0)
wd-entry-f   1/ψ12 − 1                               FALSE
wd-x-f       X/(2 + ψ12) − X/2                       FALSE
wd-r1-f      r = 1: 1/(1 + (XᵀX)[0,0]) − 1/2         TRUE (XᵀX = 1 at r = 1) -- control
wd-r1-f2     r = 1: 1/(1 + (PᵀP)[0,0]) − 1           FALSE (PᵀP > 0 generic)
"""
from stiefelsym import admissible, claim

R2 = admissible(n_max=4, n_min=2, r_in=(2,))
R1 = admissible(n_max=3, r_min=1, r_max=1)


@claim("wd-inv-f", kind="id", sizes=R2)
def inv_f(s):
    p = s.Psi[0, 1]
    return {"x": 1 / (1 + p) - 1}


@claim("wd-inv-t", kind="id", sizes=R2)
def inv_t(s):
    p = s.Psi[0, 1]
    return {"x": (1 + p) * (1 / (1 + p)) - 1}


@claim("wd-entry-f", kind="id", sizes=R2)
def entry_f(s):
    p = s.Psi[0, 1]
    return {"x": 1 / p - 1}


@claim("wd-x-f", kind="id", sizes=R2)
def x_f(s):
    p = s.Psi[0, 1]
    return {"x": s.X / (2 + p) - s.X / 2}


@claim("wd-r1-t", kind="id", sizes=R1)
def r1_t(s):
    return {"x": 1 / (1 + (s.X.T @ s.X)[0, 0]) - s.q(1, 2)}


@claim("wd-r1-f2", kind="id", sizes=R1)
def r1_f2(s):
    return {"x": 1 / (1 + (s.P.T @ s.P)[0, 0]) - 1}
