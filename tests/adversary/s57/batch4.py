"""Batch 4: a group that errs (division by an identically zero expression) beside a group that
fails or holds."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4)


def _sq(s):
    acc = s.q(0)
    for i in range(s.n):
        for j in range(s.r):
            acc = acc + s.X[i, j] * s.X[i, j]
    return acc


@claim("e1-div0-unread-true-read", kind="id", sizes=SZ)
def e1(s):
    """1/(tr X^T X - r) * 0 in the unread group (undefined), a true read check."""
    z = s.tr(s.X.T @ s.X) - s.q(s.r)
    return {"div": (s.X.T @ s.X - s.Ir) / z, "read": _sq(s) - s.q(s.r)}


@claim("e2-div0-read-false-unread", kind="id", sizes=SZ)
def e2(s):
    """undefined read check, false unread check."""
    z = _sq(s) - s.q(s.r)
    return {"div": z / z, "wrong": s.X.T @ s.X - 2 * s.Ir}
