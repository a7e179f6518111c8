"""Batch 2: engine constants on R^n (twisted.reflection, eigenspace_projector), second points,
generics, Count/Rank, Inverse, expect='fails', tricky keys."""
from stiefelsym import admissible, claim, Rank, Count
from stiefelsym import twisted, systems

SZ = admissible(n_max=4)


def _sq(s):
    acc = s.q(0)
    for i in range(s.n):
        for j in range(s.r):
            acc = acc + s.X[i, j] * s.X[i, j]
    return acc


def READ(s):
    return _sq(s) - s.q(s.r)      # true on V


@claim("c1-reflection", kind="id", sizes=SZ)
def c1(s):
    """(X^T S1 X)^2 = I (false for r < n)."""
    S1 = twisted.reflection(s)
    M = s.X.T @ S1 @ s.X
    return {"read": READ(s), "refl": M @ M - s.Ir}


@claim("c1b-reflection-alone", kind="id", sizes=SZ)
def c1b(s):
    """(X^T S1 X)^2 = I (false for r < n), no other check."""
    S1 = twisted.reflection(s)
    M = s.X.T @ S1 @ s.X
    return {"refl": M @ M - s.Ir}


@claim("c2-projector", kind="id", sizes=SZ)
def c2(s):
    """(X^T D X)^2 = X^T D X (false)."""
    D = twisted.eigenspace_projector(s)
    M = s.X.T @ D @ s.X
    return {"read": READ(s), "proj": M @ M - M}


@claim("c3-second-point", kind="id", sizes=SZ)
def c3(s):
    """tr(X^T Y) = r (false)."""
    return {"read": READ(s), "XY": s.tr(s.X.T @ s.Y) - s.q(s.r)}


@claim("c3t-second-point-true", kind="id", sizes=SZ)
def c3t(s):
    """Y^T Y = I and Y^T Q + Q^T Y = 0 (true)."""
    return {"read": READ(s), "YY": s.Y.T @ s.Y - s.Ir, "YQ": s.Y.T @ s.Q + s.Q.T @ s.Y}


@claim("c4-generic", kind="id", sizes=SZ)
def c4(s):
    """tr(G^T X X^T G) = tr(G^T G) (false unless r = n)."""
    G = s.generic("G", "n", "r")
    return {"read": READ(s), "G": s.tr(G.T @ s.X @ s.X.T @ G) - s.tr(G.T @ G)}


@claim("c5-count-rank", kind="dim", sizes=SZ)
def c5(s):
    """rank X = r (true), rank of Phi = 2 (true for generic? claimed 3: false), count."""
    return {"read": READ(s), "rankX": Rank(s.X, s.r), "rankPhi": Rank(s.Phi, 3), "count": Count(s.r, s.r)}


@claim("c6-expect-fails", kind="id", sizes=SZ, expect="fails", fails_at=lambda n, r: True,
       erratum="a wrong sign")
def c6(s):
    """X^T X + I = 0 (false, expected to fail)."""
    return {"read": READ(s), "wrong": s.X.T @ s.X + s.Ir}


@claim("c7-keys", kind="id", sizes=SZ)
def c7(s):
    """tricky keys: quotes, commas; true read check and a false unread one named like two keys."""
    return {"read": READ(s), "x', 'read": s.X.T @ s.X - 2 * s.Ir, "": s.tr(s.X.T @ s.P)}


@claim("c8-one-key-false", kind="id", sizes=SZ)
def c8(s):
    """one key false."""
    return {"only": READ(s) + s.X.T[0, 0] - s.X.T[0, 0] + s.tr(s.X.T @ s.X) - s.q(s.r) + s.q(1)}


@claim("c9-double-point", kind="id", sizes=SZ)
def c9(s):
    """double point: X^T Y = I holds by construction (true); tr(Y^T Y) = r (false?)."""
    z = systems.double_point(s)
    return {"read": READ(s), "XtY": z["X"].T @ z["Y"] - s.Ir, "YtY": s.tr(z["Y"].T @ z["Y"]) - s.q(s.r)}


@claim("c10-lam-resolvent", kind="id", sizes=SZ)
def c10(s):
    """X^T R(lam) X (lam I - X^T A X) = I  (false)."""
    R = s.resolvent(s.lam)
    M = s.X.T @ R @ s.X
    return {"read": READ(s), "res": M @ (s.lam * s.Ir - s.X.T @ s.A @ s.X) - s.Ir}
