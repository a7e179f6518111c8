"""As tape_on_dual.py, but H also holds a realified matrix (reverse mode: "a block matrix" is Unsupported), so t.gradient takes 2nr forward passes: the check on t (first-level dual numbers) is then made at a
point of the SECOND level (u = t.tangent(e_ij), dual over dual), where `_refuse_foreign_numbers` does not look
(t's numbers are dual) and the check compares ... which parts?
  E(u) = tr(realify(XᵀX, XᵀX)) = 2tr(XᵀX) (the same on both sides).
  f: value ½<y, y> (gradient y), declared G(y) = y + y² − y (right at projectors only).
  Honest: ∂(H + E)/∂X = −½(B + Bᵀ)X + ∂E/∂X;  d_V: −½(B + Bᵀ)V + d_V ∂E/∂X.
  r81b-tf-true:   d_V ∂(H+E)/∂X = −½(B + Bᵀ)V + d_V ∂E/∂X                      TRUE
  r81b-tf-false:  d_V ∂(H+E)/∂X = d_V ∂(<x_u², B> + E)/∂X                        FALSE
  controls with the honest gradient y: r81b-tfc-true / -false.
  One level (s.gradient, check on the derivative's... no: on u's own scene with the bad gradient, forward passes):
  r81b-tf1-true:  ∂(H+E)/∂X with f.grad(u, x_u) = −½(B+Bᵀ)X + ∂E/∂X  TRUE (refusal expected: G is not the gradient off V)
  r81b-tf1-false: = ∂(<x_u², B> + E)/∂X                               FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _bad():
    return MatrixFunction(lambda w, y: w.killing(y, y) / 2, lambda w, y: y + y @ y - y, "½<y,y>")


def _good():
    return MatrixFunction(lambda w, y: w.killing(y, y) / 2, lambda w, y: y, "½<y,y>")


def _xu(u):
    return u.X @ u.X.T


def E(u):
    K = u.X.T @ u.X
    return u.tr(u.realify(K, K))


def _d(s, f, B, V):
    return s.d(lambda t: t.gradient(lambda u: E(u) + u.killing(f.grad(t, _xu(u)), B))[0], {"X": V})


def _dE(s, V):
    return s.d(lambda t: t.gradient(E)[0], {"X": V})


def _decl(s, B, V):
    return s.d(lambda t: t.gradient(lambda u: u.killing(_xu(u) @ _xu(u), B) + E(u))[0], {"X": V})


def _data(s):
    return GL_N.generic(s, "B"), s.fresh("n", "r")


@claim("r81b-tf-true", kind="id", sizes=SZ)
def tf_true(s):
    B, V = _data(s)
    return {"d ∂(H+E)/∂X = −½(B+Bᵀ)V + d∂E": _d(s, _bad(), B, V) + (B + B.T) @ V / 2 - _dE(s, V)}


@claim("r81b-tf-false", kind="id", sizes=SZ)
def tf_false(s):
    B, V = _data(s)
    return {"d ∂(H+E)/∂X = d ∂(<x², B> + E)/∂X": _d(s, _bad(), B, V) - _decl(s, B, V)}


@claim("r81b-tfc-true", kind="id", sizes=SZ)
def tfc_true(s):
    B, V = _data(s)
    return {"d ∂(H+E)/∂X = −½(B+Bᵀ)V + d∂E": _d(s, _good(), B, V) + (B + B.T) @ V / 2 - _dE(s, V)}


@claim("r81b-tfc-false", kind="id", sizes=SZ)
def tfc_false(s):
    B, V = _data(s)
    return {"d ∂(H+E)/∂X = d ∂(<x², B> + E)/∂X": _d(s, _good(), B, V) - _decl(s, B, V)}


@claim("r81b-tf1-true", kind="id", sizes=SZ)
def tf1_true(s):
    B, V = _data(s)
    f = _bad()
    g = s.gradient(lambda u: E(u) + u.killing(f.grad(u, _xu(u)), B))[0]
    return {"∂(H+E)/∂X = −½(B+Bᵀ)X + ∂E": g + (B + B.T) @ s.X / 2 - s.gradient(E)[0]}


@claim("r81b-tf1-false", kind="id", sizes=SZ)
def tf1_false(s):
    B, V = _data(s)
    f = _bad()
    g = s.gradient(lambda u: E(u) + u.killing(f.grad(u, _xu(u)), B))[0]
    return {"∂(H+E)/∂X = ∂(<x², B> + E)": g - s.gradient(lambda u: u.killing(_xu(u) @ _xu(u), B) + E(u))[0]}
