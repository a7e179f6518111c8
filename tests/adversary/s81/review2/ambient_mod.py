"""A declared gradient right modulo the constraints of V(n, r) only, taken at a point that moves with the scene
(x_t = t.X t.Xᵀ, a projector on V(n, r)), inside ambient operations (s.gradient, the canonical bracket) and the Dirac
bracket.
  f: value ½<y, y> (gradient y), declared G(y) = y + y² − y  (= y at a projector: the check at the base point passes).
  H(t) = <f.grad(t, x_t), B> = <x_t, B> (the honest function);  H'(t) = <x_t², B> (what the declared gradient gives).
  ∂H/∂X = −½(B + Bᵀ)X.  ∂H'/∂X ≠ ∂H/∂X on V(n, r): d(x² − x) = ẋx + xẋ − ẋ; for a normal V = XS (S symmetric)
  ẋ = 2XSXᵀ and ẋx + xẋ − ẋ = 2XSXᵀ ≠ 0 (numpy: truth_check.py.in).
  r81b-am-grad-true:   ∂H/∂X = ∂<x_t, B>/∂X        TRUE
  r81b-am-grad-false:  ∂H/∂X = ∂<x_t², B>/∂X       FALSE
  r81b-am-cb-true / -false: the canonical bracket {H, K}_0, K = tr(Cᵀ P), against {<x_t, B>, K}_0 / {<x_t², B>, K}_0
  Dirac bracket (depends on H on T*V only, where H = H'):
  r81b-am-db-true:     {H, K} = {<x_t², B>, K}     TRUE  (a wrong refutation would be "fails")
  r81b-am-db-false:    {H, K} = 0                   FALSE ({<XXᵀ, B>, tr(CᵀP)} ≠ 0 for generic B, C)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _f():
    return MatrixFunction(lambda u, y: u.killing(y, y) / 2, lambda u, y: y + y @ y - y, "½<y, y>")


def _x(t):
    return t.X @ t.X.T


def _fns(s):
    B, C = GL_N.generic(s, "B"), s.fresh("n", "r")
    f = _f()
    H = lambda t: t.killing(f.grad(t, _x(t)), B)
    H1 = lambda t: t.killing(_x(t), B)
    H2 = lambda t: t.killing(_x(t) @ _x(t), B)
    K = lambda t: t.tr(C.T @ t.P)
    return H, H1, H2, K


@claim("r81b-am-grad-true", kind="id", sizes=SZ)
def g_true(s):
    H, H1, H2, K = _fns(s)
    return {"∂H/∂X = ∂<x, B>/∂X": s.gradient(H)[0] - s.gradient(H1)[0]}


@claim("r81b-am-grad-false", kind="id", sizes=SZ)
def g_false(s):
    H, H1, H2, K = _fns(s)
    return {"∂H/∂X = ∂<x², B>/∂X": s.gradient(H)[0] - s.gradient(H2)[0]}


@claim("r81b-am-cb-true", kind="id", sizes=SZ)
def cb_true(s):
    H, H1, H2, K = _fns(s)
    return {"{H,K}_0 = {H1,K}_0": s.canonical_bracket(H, K) - s.canonical_bracket(H1, K)}


@claim("r81b-am-cb-false", kind="id", sizes=SZ)
def cb_false(s):
    H, H1, H2, K = _fns(s)
    return {"{H,K}_0 = {H2,K}_0": s.canonical_bracket(H, K) - s.canonical_bracket(H2, K)}


@claim("r81b-am-db-true", kind="id", sizes=SZ)
def db_true(s):
    H, H1, H2, K = _fns(s)
    return {"{H,K} = {H2,K}": s.bracket(H, K) - s.bracket(H2, K)}


@claim("r81b-am-db-false", kind="id", sizes=SZ)
def db_false(s):
    H, H1, H2, K = _fns(s)
    return {"{H,K} = 0": s.bracket(H, K)}
