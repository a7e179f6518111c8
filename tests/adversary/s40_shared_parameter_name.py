"""Round 11, JC: at r = n a claim's generic matrix of one name, s.general_params("G", size, size, spaces), on
ℝⁿ × ℝⁿ and on ℝʳ × ℝʳ (the parameters were keyed by the name and the numbers of the size only: one matrix at
r = n, two at r < n).  The exact method's equivariant chart (X = X₀, O(n) on the left and O(r) on the right)
takes every generic matrix to move with its sides; one matrix that is both fixed by O(r) (on ℝⁿ) and moved by it
(on ℝʳ) is neither, and XG = GX was proved at X₀ = I."""
from stiefelsym import Size, SizeSpec, claim

SQ = SizeSpec((Size(3, 3), Size(4, 4)), n_min=3, n_max=4, r_is_n=True)        # stated at r = n only
BOTH = SizeSpec((Size(3, 2), Size(3, 3)))


def _two(s):
    return s.general_params("G", s.n, s.n, ("n", "n")), s.general_params("G", s.r, s.r, ("r", "r"))


@claim("adv-s40-shared-name-commutes", paper="adv", kind="id", sizes=SQ)
def commutes(s):
    """False: XG₂ = G₁X (at r = n, G₁ and G₂ of one name)."""
    G1, G2 = _two(s)
    return {"XG - GX": s.X @ G2 - G1 @ s.X}


@claim("adv-s40-shared-name-conjugate", paper="adv", kind="id", sizes=SQ)
def conjugate(s):
    """False: XᵀG₁X = G₂."""
    G1, G2 = _two(s)
    return {"X^T G X - G": s.X.T @ G1 @ s.X - G2}


@claim("adv-s40-shared-name-true", paper="adv", kind="id", sizes=SQ)
def trace_true(s):
    """True at r = n: tr(XᵀG₁X) = tr G₁ (X orthogonal)."""
    G1, _ = _two(s)
    return {"tr": s.tr(s.X.T @ G1 @ s.X) - s.tr(G1)}


@claim("adv-s40-shared-name-one-space-true", paper="adv", kind="id", sizes=BOTH)
def one_space_true(s):
    """True: G₂ of one name and one space, asked twice, is one matrix (XᵀX = I_r)."""
    _, G2 = _two(s)
    return {"G2 - G2": G2 @ s.X.T @ s.X - s.general_params("G", s.r, s.r, ("r", "r"))}
