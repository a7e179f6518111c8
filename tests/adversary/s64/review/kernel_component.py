# ruff: noqa
"""Kernel certificates that hold on one component of O(n) only (r64)."""
from stiefelsym import Rank, claim, elementary, admissible


@claim("r64-kcomp-2", kind="dim", sizes=[(2, 2)])
def kcomp2(s):
    """M = diag(det(XᵀY) - 1, 1) at (2,2): rank 1 where X, Y lie on one component of O(2), 2 on mixed pairs; printed 1, with the
    kernel e1 (M e1 = 0 on pairs of one component only).  False on O(2)."""
    d = elementary(s, s.X.T @ s.Y, 2)[2]
    M = s.mat([[d - 1, 0], [0, 1]], ("?", "?"))
    K = s.mat([[1], [0]], ("?", "?"))
    return {"rank": Rank(M, 1, kernel=K)}


@claim("r64-kcomp-3", kind="dim", sizes=[(3, 3)])
def kcomp3(s):
    """The same at (3,3) with det(XᵀY) = e3: rank 1 on SO(3), 2 on the other component.  False on O(3)."""
    d = elementary(s, s.X.T @ s.Y, 3)[3]
    M = s.mat([[d - 1, 0], [0, 1]], ("?", "?"))
    K = s.mat([[1], [0]], ("?", "?"))
    return {"rank": Rank(M, 1, kernel=K)}


@claim("r64-kcomp-2-nok", kind="dim", sizes=[(2, 2)])
def kcomp2_nok(s):
    """The same as r64-kcomp-2 without the kernel (control)."""
    d = elementary(s, s.X.T @ s.Y, 2)[2]
    M = s.mat([[d - 1, 0], [0, 1]], ("?", "?"))
    return {"rank": Rank(M, 1)}
