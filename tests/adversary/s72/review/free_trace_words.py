"""s72 review: trace words of generic symmetric and skew letters under the dimension-free method (attempts W1-W10).
Each docstring says whether the statement is true; fixed sizes decide it too."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=4)


def letters(s, m="r"):
    S1 = s.generic("S1", m, m, "sym")
    S2 = s.generic("S2", m, m, "sym")
    K1 = s.generic("K1", m, m, "skew")
    K2 = s.generic("K2", m, m, "skew")
    K3 = s.generic("K3", m, m, "skew")
    return S1, S2, K1, K2, K3


@claim("s72-w-kskssk", paper="No", kind="id", section="t", sizes=SIZES)
def w1(s):
    """tr(K S K S K) = 0 (true: its transpose is minus itself)."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"tr": s.tr(K1 @ S1 @ K1 @ S1 @ K1)}


@claim("s72-w-k1k2k3", paper="No", kind="id", section="t", sizes=SIZES)
def w2(s):
    """tr(K1 K2 K3) = 0 (false for r >= 3)."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"tr": s.tr(K1 @ K2 @ K3)}


@claim("s72-w-k1k2k3-sum", paper="No", kind="id", section="t", sizes=SIZES)
def w3(s):
    """tr(K1 K2 K3) + tr(K3 K2 K1) = 0 (true)."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"tr": s.tr(K1 @ K2 @ K3) + s.tr(K3 @ K2 @ K1)}


@claim("s72-w-sksk", paper="No", kind="id", section="t", sizes=SIZES)
def w4(s):
    """tr(S K S K) = 0 (false for r >= 2)."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"tr": s.tr(S1 @ K1 @ S1 @ K1)}


@claim("s72-w-s1s2k", paper="No", kind="id", section="t", sizes=SIZES)
def w5(s):
    """tr(S1 S2 K) = 0 (false for r >= 2)."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"tr": s.tr(S1 @ S2 @ K1)}


@claim("s72-w-k1s1k2s2", paper="No", kind="id", section="t", sizes=SIZES)
def w6(s):
    """tr(K1 S1 K2 S2) = tr(K2 S1 K1 S2) (true: transpose of one is the other rotated: tr(S2ᵀK2ᵀS1ᵀK1ᵀ) = tr(S2 K2 S1 K1))."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"d": s.tr(K1 @ S1 @ K2 @ S2) - s.tr(K2 @ S1 @ K1 @ S2)}


@claim("s72-w-k1s1k2s2-false", paper="No", kind="id", section="t", sizes=SIZES)
def w7(s):
    """tr(K1 S1 K2 S2) = tr(K1 S2 K2 S1) (TRUE: the transpose of the right side is a rotation of the left)."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"d": s.tr(K1 @ S1 @ K2 @ S2) - s.tr(K1 @ S2 @ K2 @ S1)}


@claim("s72-w-k1s1k2s2-wrong", paper="No", kind="id", section="t", sizes=SIZES)
def w8(s):
    """tr(K1 S1 K2 S2) = −tr(K1 S2 K2 S1) (false)."""
    S1, S2, K1, K2, K3 = letters(s)
    return {"d": s.tr(K1 @ S1 @ K2 @ S2) + s.tr(K1 @ S2 @ K2 @ S1)}


@claim("s72-w-mixed-x", paper="No", kind="id", section="t", sizes=SIZES)
def w9(s):
    """tr(Xᵀ Kn X K) = 0 with Kn skew on R^n, K skew on R^r (false for r >= 2)."""
    Kn = s.generic("Kn", "n", "n", "skew")
    K = s.generic("K", "r", "r", "skew")
    return {"tr": s.tr(s.X.T @ Kn @ s.X @ K)}


@claim("s72-w-mixed-x-true", paper="No", kind="id", section="t", sizes=SIZES)
def w10(s):
    """tr(Xᵀ Sn X K) = 0 with Sn symmetric on R^n, K skew on R^r (true: XᵀSnX is symmetric)."""
    Sn = s.generic("Sn", "n", "n", "sym")
    K = s.generic("K", "r", "r", "skew")
    return {"tr": s.tr(s.X.T @ Sn @ s.X @ K)}


@claim("s72-w-sym-gen-name", paper="No", kind="id", section="t", sizes=SIZES)
def w11(s):
    """S (sym, named G) − G (general, named G) = 0 (false: two matrices sharing a name)."""
    return {"d": s.generic("G", "r", "r", "sym") - s.generic("G", "r", "r")}


@claim("s72-w-sym-skew-name", paper="No", kind="id", section="t", sizes=SIZES)
def w12(s):
    """tr(S K) with S sym named G and K skew named G: 0 (true whatever the names)."""
    return {"d": s.tr(s.generic("G", "n", "n", "sym") @ s.generic("G", "n", "n", "skew"))}


@claim("s72-w-sym-skew-name-false", paper="No", kind="id", section="t", sizes=SIZES)
def w13(s):
    """tr(S(S + K)) = tr(S S) with S sym named G and K skew named G (TRUE: tr(SK) = 0; kept as a control)."""
    S = s.generic("G", "n", "n", "sym")
    K = s.generic("G", "n", "n", "skew")
    return {"d": s.tr(S @ (S + K)) - s.tr(S @ S)}
