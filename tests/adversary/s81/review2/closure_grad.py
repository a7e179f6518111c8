"""The check made on the claim's scene s inside the function of s.gradient, at a point x and with a declared gradient
that do NOT move (constants of s), of a MatrixFunction whose VALUE closes over the gradient's scene t:
    F_t = MatrixFunction(lambda u, y: u.killing(y, t.X t.Xᵀ), lambda u, y: s.X s.Xᵀ);   H(t) = <F_t.grad(s, x), B>
F_t.grad(s, x) is (the engine's promise) the gradient at x of y ↦ <y, t.X t.Xᵀ>, i.e. t.X t.Xᵀ, so
    H(t) = <t.X t.Xᵀ, B> = −½ tr(X Xᵀ B),  dH[V] = −½ tr(Xᵀ(B + Bᵀ)V),  ∂H/∂X = −½(B + Bᵀ)X   (≠ 0).
The declared gradient s.X s.Xᵀ equals t.X t.Xᵀ at the base point only (the check there passes), and it is a
constant of t: an engine that takes the check's adjoint as 0 gives ∂H/∂X = 0.
  r81b-cg-true:   ∂H/∂X = −½(B + Bᵀ)X      TRUE
  r81b-cg-false:  ∂H/∂X = 0                FALSE
The same through the canonical bracket {H, K}_0 with K(t) = tr(Cᵀ t.P) (K_P = C, K_X = 0): {H, K}_0 = tr(H_Xᵀ C):
  r81b-cgb-true:  {H, K}_0 = −½ tr(Xᵀ(B + Bᵀ)C)   TRUE ;  r81b-cgb-false: {H, K}_0 = 0   FALSE
Controls (value and gradient both read the scene they are given, check on t):
  r81b-cgc-true / r81b-cgc-false (the same right-hand sides).
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _F(s, t):
    return MatrixFunction(lambda u, y: u.killing(y, t.X @ t.X.T), lambda u, y: s.X @ s.X.T, "F_t")


def _H(s, x, B):
    return lambda t: t.killing(_F(s, t).grad(s, x), B)


def _Hc(x, B):
    G = MatrixFunction(lambda u, y: u.killing(y, u.X @ u.X.T), lambda u, y: u.X @ u.X.T, "G")
    return lambda t: t.killing(G.grad(t, x), B)


def _data(s):
    return GL_N.generic(s, "x"), GL_N.generic(s, "B")


def _rhs(s, B):
    return (B + B.T) @ s.X * s.q(-1, 2)


@claim("r81b-cg-true", kind="id", sizes=SZ)
def cg_true(s):
    x, B = _data(s)
    return {"∂H/∂X = −½(B+Bᵀ)X": s.gradient(_H(s, x, B))[0] - _rhs(s, B)}


@claim("r81b-cg-false", kind="id", sizes=SZ)
def cg_false(s):
    x, B = _data(s)
    return {"∂H/∂X = 0": s.gradient(_H(s, x, B))[0]}


@claim("r81b-cgb-true", kind="id", sizes=SZ)
def cgb_true(s):
    x, B = _data(s)
    C = s.fresh("n", "r")
    K = lambda t: t.tr(C.T @ t.P)
    return {"{H,K}_0 = tr(H_Xᵀ C)": s.canonical_bracket(_H(s, x, B), K) - s.tr(_rhs(s, B).T @ C)}


@claim("r81b-cgb-false", kind="id", sizes=SZ)
def cgb_false(s):
    x, B = _data(s)
    C = s.fresh("n", "r")
    K = lambda t: t.tr(C.T @ t.P)
    return {"{H,K}_0 = 0": s.canonical_bracket(_H(s, x, B), K)}


@claim("r81b-cgc-true", kind="id", sizes=SZ)
def cgc_true(s):
    x, B = _data(s)
    return {"∂H/∂X = −½(B+Bᵀ)X": s.gradient(_Hc(x, B))[0] - _rhs(s, B)}


@claim("r81b-cgc-false", kind="id", sizes=SZ)
def cgc_false(s):
    x, B = _data(s)
    return {"∂H/∂X = 0": s.gradient(_Hc(x, B))[0]}
