"""Round 13 (the exact zero test beyond the ring's parameters): generic operators beyond the exact ring's parameters (two 9 x 9 generic matrices and a quadratic form
of their product): a false identity and a true one."""
from stiefelsym import Size, SizeSpec, claim

S = SizeSpec((Size(9, 1),))


@claim("adv-s40-big-false", paper="adv", kind="id", sizes=S)
def big_false(s):
    """False: tr(GH) = tr(GH^T) for generic G, H."""
    G, H = s.generic("G", "n", "n"), s.generic("H", "n", "n")
    return {"tr(GH) - tr(GH^T)": (G @ H).trace() - (G @ H.T).trace()}


@claim("adv-s40-big-true", paper="adv", kind="id", sizes=S)
def big_true(s):
    """True: tr(GH) = tr(HG) for generic G, H, and tr(GH X X^T) = tr(X^T G H X)."""
    G, H = s.generic("G", "n", "n"), s.generic("H", "n", "n")
    return {"tr(GH) - tr(HG)": (G @ H).trace() - (H @ G).trace(),
            "cyclic": (G @ H @ s.X @ s.X.T).trace() - (s.X.T @ G @ H @ s.X).trace()}
