"""Batch 3: corrections of an erratum claim proved in groups; a heavy unread group under --timeout."""
from stiefelsym import admissible, claim, det

SZ = admissible(n_max=4)


def _sq(s):
    acc = s.q(0)
    for i in range(s.n):
        for j in range(s.r):
            acc = acc + s.X[i, j] * s.X[i, j]
    return acc


@claim("d1-erratum", kind="id", sizes=SZ, fails_at=lambda n, r: True, erratum="a factor 2")
def d1(s):
    """sum of squares = 2r and X^T X = I (the first is wrong)."""
    return {"read": _sq(s) - 2 * s.q(s.r), "XtX": s.X.T @ s.X - s.Ir}


@d1.claim.correction("sum of squares = r, and a false unread check")
def d1_bad(s):
    return {"read": _sq(s) - s.q(s.r), "XtX": s.X.T @ s.X - 2 * s.Ir}


@d1.claim.correction("sum of squares = r")
def d1_good(s):
    return {"read": _sq(s) - s.q(s.r), "XtX": s.X.T @ s.X - s.Ir}


@claim("d2-heavy", kind="id", sizes=SZ)
def d2(s):
    """a heavy unread check (true: det of the resolvent pencil identity) and a false read check."""
    R = s.resolvent(s.lam)
    M = s.X.T @ R @ s.X + s.P.T @ R @ s.P
    heavy = det(s, M @ M @ M) - det(s, M) * det(s, M) * det(s, M)
    return {"heavy": heavy, "read": _sq(s) - s.q(s.r) + s.q(1)}
