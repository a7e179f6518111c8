"""Class 1 (entries read through a block, chart choice): the generic block on R^{n−r} joined into R^n.

B = (0_{r×r}; G) with G = s.generic("G", "n-r", "r") a generic (n−r)×r block, joined by `block` (the guide's
spelling).  For a point X of V(n, r) and a generic G, XᵀB = X₂ᵀG (X₂ the last n − r rows of X): nonzero unless
X₂ = 0, i.e. unless X = X₀ up to O(r) (the equivariant chart's point).
 b-xtb-false:  XᵀB = 0: FALSE (at X = X₀ it is 0; at a generic point not).
 b-xtb-true:   XᵀB − X₂ᵀG... written (B ⊥ X only at X₀) — TRUE twin: BᵀB − GᵀG = 0 (0ᵀ0 + GᵀG): TRUE.
 b-trace-false: tr(BᵀXXᵀB) = 0: FALSE (= |X₂ᵀG|² > 0 generically).
 b-proj-false: (I − XXᵀ)B − B = 0: FALSE (= −XXᵀB).
 b-proj-true:  (I − XXᵀ)B − B + XXᵀB = 0: TRUE.
"""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


def _B(s):
    G = s.generic("G", "n-r", "r")
    return block([[s.zeros(s.r, s.r, ("r", "r"))], [G]])


@claim("b-xtb-false", kind="id", sizes=SZ)
def b_xtb_false(s):
    return {"XtB": s.X.T @ _B(s)}


@claim("b-xtb-true", kind="id", sizes=SZ)
def b_xtb_true(s):
    G = s.generic("G", "n-r", "r")
    B = _B(s)
    return {"BtB - GtG": B.T @ B - G.T @ G}


@claim("b-trace-false", kind="id", sizes=SZ)
def b_trace_false(s):
    B = _B(s)
    return {"tr": s.tr(B.T @ s.X @ s.X.T @ B)}


@claim("b-proj-false", kind="id", sizes=SZ)
def b_proj_false(s):
    B = _B(s)
    return {"proj": (s.In - s.X @ s.X.T) @ B - B}


@claim("b-proj-true", kind="id", sizes=SZ)
def b_proj_true(s):
    B = _B(s)
    return {"proj": (s.In - s.X @ s.X.T) @ B - B + s.X @ s.X.T @ B}


def _B_untyped(s):
    """B passed through an untyped identity ("?", "?") of size n: (I_? B) then meets R^n."""
    n = int(s.n)
    E = s.mat([[1 if i == j else 0 for j in range(n)] for i in range(n)], ("?", "?"))
    return E @ _B(s)


@claim("b-untyped-false", kind="id", sizes=SZ)
def b_untyped_false(s):
    """XᵀB = 0 through an untyped identity: FALSE."""
    return {"XtB": s.X.T @ _B_untyped(s)}


@claim("b-untyped-true", kind="id", sizes=SZ)
def b_untyped_true(s):
    """(I − XXᵀ)B − B + XXᵀB = 0 through an untyped identity: TRUE."""
    B = _B_untyped(s)
    return {"proj": (s.In - s.X @ s.X.T) @ B - B + s.X @ s.X.T @ B}


@claim("b-sym-false", kind="id", sizes=SZ)
def b_sym_false(s):
    """tr(Bᵀ XXᵀ B) = 0 through an untyped identity: FALSE (|X₂ᵀG|²)."""
    B = _B_untyped(s)
    return {"tr": s.tr(B.T @ s.X @ s.X.T @ B)}
