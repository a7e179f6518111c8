"""Adversary (generic kinds): symmetric and skew generic matrices large enough to be drawn as one block
(m(m+1)/2 >= 64: n >= 11 for sym, n >= 12 for skew), true and false statements."""
from stiefelsym import claim, Size, SizeSpec

BIG = SizeSpec((Size(11, 1), Size(12, 1), Size(12, 12)))


@claim("adv-gk-big-true", paper="adv", kind="id", sizes=BIG)
def big_true(s):
    """True: S symmetric, K skew, tr(SK) = 0, tr(S_n) + tr(S_r) - tr(S_n) - tr(S_r) trivial, tr(X^T K X) = 0."""
    S, K = s.generic("S", "n", "n", "sym"), s.generic("K", "n", "n", "skew")
    Sr, Kr = s.generic("Sr", "r", "r", "sym"), s.generic("Kr", "r", "r", "skew")      # one name, one parameter
    return {"S - S^T": S - S.T, "K + K^T": K + K.T, "tr(SK)": (S @ K).trace(),
            "tr(XtKX)": (s.X.T @ K @ s.X).trace(), "Sr - Sr^T": Sr - Sr.T, "Kr + Kr^T": Kr + Kr.T,
            "tr(A K)": (s.A @ K).trace()}


@claim("adv-gk-big-false", paper="adv", kind="id", sizes=BIG)
def big_false(s):
    """False: S K = K S for S symmetric, K skew."""
    S, K = s.generic("S", "n", "n", "sym"), s.generic("K", "n", "n", "skew")
    return {"SK - KS": S @ K - K @ S}


@claim("adv-gk-big-false-sym-gen", paper="adv", kind="id", sizes=BIG)
def big_false_sym_gen(s):
    """False: the symmetric S is the general S of the same name (symmetrized)."""
    S, G = s.generic("S", "n", "n", "sym"), s.generic("S", "n", "n")
    return {"2S - G - G^T": S * 2 - G - G.T}


@claim("adv-gk-big-false-nr", paper="adv", kind="id", sizes=BIG)
def big_false_nr(s):
    """False at every size: tr(S_n) = tr(S_r) (at r = n two matrices too)."""
    return {"x": s.generic("S", "n", "n", "sym").trace() - s.generic("S", "r", "r", "sym").trace()}
