"""s89h1: claim parameters named like the engine's own objects (letters of the free algebra, the symbols n, r).

All FALSE (a fresh parameter is independent of the scene's objects):
 s89h1-scalar-n: s.scalar("n") - tr(I_n) = 0.
 s89h1-scalar-r: s.scalar("r") - tr(I_r) = 0.
 s89h1-generic-X: G = generic("X", n, r): GᵀG - I_r = 0.
 s89h1-generic-X-minus: G - X = 0, G = generic("X", n, r).
 s89h1-generic-P: G = generic("P", n, r): XᵀG + GᵀX = 0.
 s89h1-generic-A-sym: generic("A", n, n, "sym") - A = 0.
 s89h1-generic-Ir: generic("I_r", r, r) - I_r = 0.
 s89h1-scalar-lambda: s.scalar("lambda") - s.lam = 0.
 s89h1-scalar-kappa: s.scalar("kappa") - s.kappa = 0.
 s89h1-generic-E1: generic("E1", r, r) ... - 0 (see code).
 s89h1-generic-Xt: generic("Xt", r, n) - Xᵀ = 0.
 s89h1-scalar-tr: s.scalar("tr") ... s.scalar("n_r") etc.
 s89h1-op-X: s.sym_operator("X") applied vs generic "X".
"""
from stiefelsym import claim, admissible

S = admissible(n_max=3)


@claim("s89h1-scalar-n", kind="id", sizes=S)
def scalar_n(s):
    """scalar n = tr I_n (false)."""
    return {"r": s.scalar("n") - s.tr(s.In)}


@claim("s89h1-scalar-r", kind="id", sizes=S)
def scalar_r(s):
    """scalar r = tr I_r (false)."""
    return {"r": s.scalar("r") - s.tr(s.Ir)}


@claim("s89h1-generic-X", kind="id", sizes=S)
def generic_X(s):
    """GᵀG = I for a generic G named X (false)."""
    G = s.generic("X", "n", "r")
    return {"r": G.T @ G - s.Ir}


@claim("s89h1-generic-X-minus", kind="id", sizes=S)
def generic_X_minus(s):
    """G = X (false)."""
    return {"r": s.generic("X", "n", "r") - s.X}


@claim("s89h1-generic-P", kind="id", sizes=S)
def generic_P(s):
    """XᵀG + GᵀX = 0 for G named P (false)."""
    G = s.generic("P", "n", "r")
    return {"r": s.X.T @ G + G.T @ s.X}


@claim("s89h1-generic-A-sym", kind="id", sizes=S)
def generic_A(s):
    """generic sym named A equals A (false)."""
    return {"r": s.generic("A", "n", "n", "sym") - s.A}


@claim("s89h1-generic-Ir", kind="id", sizes=S)
def generic_Ir(s):
    """generic named I_r equals I_r (false)."""
    return {"r": s.generic("I_r", "r", "r") - s.Ir}


@claim("s89h1-scalar-lambda", kind="id", sizes=S)
def scalar_lambda(s):
    """scalar lambda = s.lam (false)."""
    return {"r": s.scalar("lambda") - s.lam}


@claim("s89h1-scalar-kappa", kind="id", sizes=S)
def scalar_kappa(s):
    """scalar kappa = s.kappa (false)."""
    return {"r": s.scalar("kappa") - s.kappa}


@claim("s89h1-scalar-epsilon", kind="id", sizes=S)
def scalar_eps(s):
    """scalar epsilon = s.eps (false)."""
    return {"r": s.scalar("epsilon") - s.eps}


@claim("s89h1-generic-Xt", kind="id", sizes=S)
def generic_Xt(s):
    """generic named Xt equals Xᵀ (false)."""
    return {"r": s.generic("Xt", "r", "n") - s.X.T}


@claim("s89h1-generic-Ainv", kind="id", sizes=S)
def generic_Ainv(s):
    """generic named Ainv times A = I (false)."""
    return {"r": s.generic("Ainv", "n", "n") @ s.A - s.In}


@claim("s89h1-generic-AA-op", kind="id", sizes=S)
def generic_AA(s):
    """a generic skew n×n named AA vs the operator AA applied to X Pᵀ (false)."""
    op = s.sym_operator("AA")
    return {"r": op(s.X @ s.P.T) - s.generic("AA", "n", "n", "skew")}


@claim("s89h1-generic-Y", kind="id", sizes=S)
def generic_Y(s):
    """GᵀG = I_r for a generic named Y (false)."""
    G = s.generic("Y", "n", "r")
    return {"r": G.T @ G - s.Ir}
