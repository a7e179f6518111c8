# ruff: noqa: E702, F401
"""s89h3 c2: ill-typed or space-mixing sums inside one trace whose words cancel by rotation.
B generic r×n, C generic n×r, D generic (n-r)×r, E generic r×(n-r).
 h3-cb-bc (ILL-TYPED for every size: an n×n matrix minus an r×r one; at r = n the spaces R^n, R^r still differ).
   A refusal (error) is the right answer; 'proved' would be a proof of a statement that is not well formed.
 h3-cb-bc-plus (ILL-TYPED; if accepted at r=n it would be tr(CB)+tr(BC) = 2tr(BC) ≠ 0: FALSE).
 h3-de-ed (ILL-TYPED: (n-r)×(n-r) minus r×r; at n=2,r=1 both 1×1).
 h3-x-trace (ILL-TYPED: tr(X - X) of an n×r matrix, words cancel to nothing).
 h3-xpt (ILL-TYPED: tr(X Pᵀ X - X Pᵀ X) n×r; words cancel).
 h3-ok-de (TRUE: tr(D E) - tr(E D) as two traces = 0, r < n).
"""
from stiefelsym import admissible, claim

SZ = [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)]


@claim("h3-cb-bc", kind="id", sizes=SZ)
def cbbc(s):
    B = s.generic("B", "r", "n"); C = s.generic("C", "n", "r")
    return {"r": s.tr(C @ B - B @ C)}


@claim("h3-cb-bc-plus", kind="id", sizes=SZ)
def cbbcp(s):
    B = s.generic("B", "r", "n"); C = s.generic("C", "n", "r")
    return {"r": s.tr(C @ B + B @ C)}


@claim("h3-de-ed", kind="id", sizes=[(2, 1), (3, 1), (3, 2), (4, 2)])
def deed(s):
    D = s.generic("D", "n-r", "r"); E = s.generic("E", "r", "n-r")
    return {"r": s.tr(D @ E - E @ D)}


@claim("h3-x-trace", kind="id", sizes=SZ)
def xtr(s):
    return {"r": s.tr(s.X - s.X)}


@claim("h3-xpt", kind="id", sizes=SZ)
def xpt(s):
    return {"r": s.tr(s.X @ s.P.T @ s.X - s.X @ s.P.T @ s.X)}


@claim("h3-ok-de", kind="id", sizes=[(2, 1), (3, 1), (3, 2), (4, 2)])
def okde(s):
    D = s.generic("D", "n-r", "r"); E = s.generic("E", "r", "n-r")
    return {"r": s.tr(D @ E) - s.tr(E @ D)}
