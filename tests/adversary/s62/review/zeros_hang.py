"""Trivially true statements with zero blocks: where the time goes (sz-t-zeros-2r of sizes_arith.py took 140 s
under exact, inconclusive, and over 300 s under modular)."""
from stiefelsym import admissible, block, claim

ALL = admissible(n_max=4)


@claim("zh-zero-2r", kind="id", sizes=ALL)
def zero_2r(s):
    """The zero 2r x r matrix is zero."""
    return {"r": s.zeros(s.r * 2, s.r, ("r+r", "r"))}


@claim("zh-zero-block-times", kind="id", sizes=ALL)
def zero_block_times(s):
    """[0; 0·I] XᵀX = 0."""
    return {"r": block([[s.zeros(s.r, s.r, ("r", "r"))], [0 * s.Ir]]) @ (s.X.T @ s.X)}


@claim("zh-zero-times", kind="id", sizes=ALL)
def zero_times(s):
    """0·I_r XᵀX = 0."""
    return {"r": (0 * s.Ir) @ (s.X.T @ s.X)}


@claim("zh-zeros-times", kind="id", sizes=ALL)
def zeros_times(s):
    """zeros(r, r) XᵀX = 0."""
    return {"r": s.zeros(s.r, s.r, ("r", "r")) @ (s.X.T @ s.X)}


@claim("zh-orig", kind="id", sizes=ALL)
def orig(s):
    """zeros(2r, r) − [0; 0·I] XᵀX = 0 (sz-t-zeros-2r of sizes_arith.py)."""
    Z = s.zeros(s.r * 2, s.r, ("r+r", "r"))
    return {"r": Z - block([[s.zeros(s.r, s.r, ("r", "r"))], [0 * s.Ir]]) @ (s.X.T @ s.X)}


@claim("zh-zero-minus-zero", kind="id", sizes=ALL)
def zero_minus_zero(s):
    """zeros(r, r) − zeros(r, r) = 0."""
    return {"r": s.zeros(s.r, s.r, ("r", "r")) - s.zeros(s.r, s.r, ("r", "r"))}


@claim("zh-zero-minus-zero-times", kind="id", sizes=ALL)
def zero_minus_zero_times(s):
    """zeros(r, r) − zeros(r, r) XᵀX = 0."""
    return {"r": s.zeros(s.r, s.r, ("r", "r")) - s.zeros(s.r, s.r, ("r", "r")) @ (s.X.T @ s.X)}


@claim("zh-min-zeros", kind="id", sizes=ALL)
def min_zeros(s):
    """zeros(2r, r) − [zeros(r, r); zeros(r, r)] = 0."""
    Z = s.zeros(s.r * 2, s.r, ("r+r", "r"))
    return {"r": Z - block([[s.zeros(s.r, s.r, ("r", "r"))], [s.zeros(s.r, s.r, ("r", "r"))]])}


@claim("zh-min-ir", kind="id", sizes=ALL)
def min_ir(s):
    """zeros(2r, r) − [0·I_r; 0·I_r] = 0."""
    Z = s.zeros(s.r * 2, s.r, ("r+r", "r"))
    return {"r": Z - block([[0 * s.Ir], [0 * s.Ir]])}


@claim("zh-min-identity", kind="id", sizes=ALL)
def min_identity(s):
    """I_{2r} − diag(I_r, I_r) = 0 (true)."""
    return {"r": s.identity(s.r * 2, "r+r") - block([[s.Ir, 0 * s.Ir], [0 * s.Ir, s.Ir]])}


@claim("zh-min-identity-false", kind="id", sizes=ALL)
def min_identity_false(s):
    """I_{2r} − diag(I_r, 2 I_r) = 0 (FALSE)."""
    return {"r": s.identity(s.r * 2, "r+r") - block([[s.Ir, 0 * s.Ir], [0 * s.Ir, 2 * s.Ir]])}


@claim("zh-h-zeros-times", kind="id", sizes=ALL)
def h_zeros_times(s):
    """zeros(2r, r) − [zeros(r, r); zeros(r, r)] XᵀX = 0 (true)."""
    Z = s.zeros(s.r * 2, s.r, ("r+r", "r"))
    return {"r": Z - block([[s.zeros(s.r, s.r, ("r", "r"))], [s.zeros(s.r, s.r, ("r", "r"))]]) @ (s.X.T @ s.X)}


@claim("zh-h-false", kind="id", sizes=ALL)
def h_false(s):
    """zeros(2r, r) − [I_r; I_r] XᵀX = 0 (FALSE)."""
    Z = s.zeros(s.r * 2, s.r, ("r+r", "r"))
    return {"r": Z - block([[s.Ir], [s.Ir]]) @ (s.X.T @ s.X)}


@claim("zh-h-identity", kind="id", sizes=ALL)
def h_identity(s):
    """[I_r; I_r] = [I_r; I_r] XᵀX written against zeros(2r, r) (true): zeros(2r, r) + [I; I] − [I; I] XᵀX."""
    Z = s.zeros(s.r * 2, s.r, ("r+r", "r"))
    B = block([[s.Ir], [s.Ir]])
    return {"r": Z + B - B @ (s.X.T @ s.X)}
