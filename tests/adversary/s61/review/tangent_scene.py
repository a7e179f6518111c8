"""The scene's tangent scene used directly by a claim."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("ts-dual-residual", paper="t", kind="id", section="2", sizes=SZ)
def ts_dual(s):
    """FALSE as a derivative: (X + eps P)ᵀ(X + eps P) − I has eps-part XᵀP + PᵀX... zero; use G."""
    G = s.generic("G", "n", "r")
    t = s.tangent({"X": G})
    return {"r": t.X.T @ t.X - t.Ir}


@claim("ts-dual-tr", paper="t", kind="id", section="2", sizes=SZ)
def ts_dual_tr(s):
    G = s.generic("G", "n", "r")
    t = s.tangent({"X": G})
    return {"r": t.tr(t.X.T @ t.X) - s.tr(s.Ir)}
