"""Class 8: claims file B (see a.py); b.py states claims of the same ids, each differing in one field that may be left out of
the graph digest.  The records of a run of A are checked with `stiefelsym check --claims b.py` (and b.py copied over
a.py's path): a record whose verdict is wrong for B's claim must be rejected.

At (3,2) on T*V: XᵀP is skew (XᵀP + PᵀX = 0), a generic 2×2 skew matrix has rank 2, and XᵀP = 0 where P = 0.
x-gen:   A Rank(XᵀP, 2) generic                    TRUE     | B Rank(XᵀP, 2, generic=False)   FALSE (P = 0)
x-count: A Count(3, 3)                             TRUE     | B Count(3, 4)                   FALSE
x-kern:  A Rank(XᵀP, 2)                            TRUE     | B Rank(XᵀP, 2, kernel=I_r)      TRUE (kernel not one: not used)
x-exp:   A XᵀX − I_r, expect holds                 TRUE     | B the same, expect="nonzero"    FALSE
x-kind:  A XᵀX − I_r kind="id"                     TRUE     | B the same, kind="not"          TRUE (kind is a label)
x-gen2:  A Rank(I_r + ΨᵀΨ, 2) generic              TRUE     | B generic=False, Rank 2         TRUE (positive definite)
x-where: A sizes r < n, XᵀX − I_r                  TRUE     | B sizes r == n only             (3,2) not stated by B
"""
from stiefelsym import Count, Rank, admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)


@claim("x-gen", kind="dim", sizes=SZ)
def x_gen(s):
    return {"rank": Rank(s.X.T @ s.P, 2, generic=False)}


@claim("x-count", kind="dim", sizes=SZ)
def x_count(s):
    return {"k": Count(3, 4)}


@claim("x-kern", kind="dim", sizes=SZ)
def x_kern(s):
    return {"rank": Rank(s.X.T @ s.P, 2, kernel=s.Ir)}


@claim("x-exp", kind="id", sizes=SZ, expect="nonzero")
def x_exp(s):
    return {"x": s.X.T @ s.X - s.Ir}


@claim("x-kind", kind="not", sizes=SZ)
def x_kind(s):
    return {"x": s.X.T @ s.X - s.Ir}


@claim("x-gen2", kind="dim", sizes=SZ)
def x_gen2(s):
    return {"rank": Rank(s.Ir + s.Psi.T @ s.Psi, 2, generic=False)}


@claim("x-where", kind="id", sizes=admissible(n_max=3, n_min=2, where=lambda n, r: r == n))
def x_where(s):
    return {"x": s.X.T @ s.X - s.Ir}
