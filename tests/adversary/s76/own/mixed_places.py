"""Stop 76's own attempt, after the review: one correction changes the shared K = XᵀP in three checks; in two of
them XᵀP is also printed where nothing changes, in the third it is not.  Every check must say its own places."""
from stiefelsym import claim


def checks(s, K):
    return {"a": K + K.T - s.Ir * 2 + s.X.T @ (s.P * s.lam) + (s.P * s.lam).T @ s.X,
            "b": K + K.T - s.Ir * 2 + s.X.T @ (s.P * s.kappa) + (s.P * s.kappa).T @ s.X,
            "c": K - s.Ir}


@claim("own-mixed-places", kind="id", sizes=[(3, 2)], fails_at=lambda n, r: True, erratum="K = XᵀP for XᵀX.")
def mixed(s):
    """As printed with K = XᵀP (false)."""
    return checks(s, s.X.T @ s.P)


@mixed.claim.correction("K = XᵀX in place of K = XᵀP")
def mixed_corrected(s):
    return checks(s, s.X.T @ s.X)
