"""s58 batch 4: the check groups in the mutation analysis (commit 04a211a).  Each claim is true, with a
check that reads entries of R^n and checks that read none; run with
`stiefelsym mutate --claims batch4.py --size 3,2 --jobs 1 --limit K`."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _sq(s):
    acc = s.q(0)
    for i in range(int(s.n)):
        for j in range(int(s.r)):
            acc = acc + s.X[i, j] * s.X[i, j]
    return acc


@claim("s58-grp-mut-a", kind="id", sizes=SZ)
def grp_mut_a(s):
    """Σ X_ij² = r (reads entries), XᵀP + PᵀX = 0 and tr(Φ Φ) relation (read nothing): TRUE."""
    return {"read": _sq(s) - s.tr(s.Ir),
            "tangent": s.X.T @ s.P + s.P.T @ s.X,
            "proj": (s.X @ s.X.T) @ (s.X @ s.X.T) - s.X @ s.X.T}


@claim("s58-grp-mut-shared", kind="id", sizes=SZ)
def grp_mut_shared(s):
    """A node shared by both groups (M = XᵀX): the read check uses M's entries, the other M itself: TRUE."""
    M = s.X.T @ s.X
    return {"read": M[0, 0] - 1,
            "orth": M @ M - s.Ir}
