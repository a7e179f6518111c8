"""A check on the derivative's scene t (dual numbers) at a point of t's OWN gradient scene u (a reverse tape over t's
dual numbers, or forward passes): t.gradient(lambda u: <f.grad(t, u.X u.Xᵀ), B>) inside s.d(lambda t: ..., V).
`_refuse_foreign_numbers` refuses only on a scene whose numbers are not dual/reverse; `_refuse_on_tape` only on a
scene that is a tape.  The check on t then sees tape (or dual-of-dual) numbers.
  f: value ½<y, y> (gradient y), declared G(y) = y + y² − y (right at projectors only, wrong off them).
  Honest: H(u) = <u.X u.Xᵀ, B>, ∂H/∂X = −½(B + Bᵀ)X, d/dε along V: −½(B + Bᵀ)V.
  Declared: H'(u) = <x_u², B>;  d/dε ∂H'/∂X ≠ −½(B + Bᵀ)V (numpy: truth_check.py.in, 'tape_on_dual').
  r81b-td-true:   d_V ∂H/∂X = −½(B + Bᵀ)V                 TRUE
  r81b-td-false:  d_V ∂H/∂X = d_V ∂<x_u², B>/∂X            FALSE
  controls (the same with the honest gradient y):  r81b-tdc-true / r81b-tdc-false
  single level (check on the claim's scene s, refused in words since s81): r81b-td0-true / -false
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


def _d(s, f, B, V):
    return s.d(lambda t: t.gradient(lambda u: u.killing(f.grad(t, _xu(u)), B))[0], {"X": V})


def _data(s):
    return GL_N.generic(s, "B"), s.fresh("n", "r")


def _decl(s, B, V):
    return s.d(lambda t: t.gradient(lambda u: u.killing(_xu(u) @ _xu(u), B))[0], {"X": V})


@claim("r81b-td-true", kind="id", sizes=SZ)
def td_true(s):
    B, V = _data(s)
    return {"d ∂H/∂X = −½(B+Bᵀ)V": _d(s, _bad(), B, V) + (B + B.T) @ V / 2}


@claim("r81b-td-false", kind="id", sizes=SZ)
def td_false(s):
    B, V = _data(s)
    return {"d ∂H/∂X = d ∂<x², B>/∂X": _d(s, _bad(), B, V) - _decl(s, B, V)}


@claim("r81b-tdc-true", kind="id", sizes=SZ)
def tdc_true(s):
    B, V = _data(s)
    return {"d ∂H/∂X = −½(B+Bᵀ)V": _d(s, _good(), B, V) + (B + B.T) @ V / 2}


@claim("r81b-tdc-false", kind="id", sizes=SZ)
def tdc_false(s):
    B, V = _data(s)
    return {"d ∂H/∂X = d ∂<x², B>/∂X": _d(s, _good(), B, V) - _decl(s, B, V)}


@claim("r81b-td0-true", kind="id", sizes=SZ)
def td0_true(s):
    B, V = _data(s)
    f = _bad()
    return {"∂H/∂X = −½(B+Bᵀ)X": s.gradient(lambda u: u.killing(f.grad(s, _xu(u)), B))[0] + (B + B.T) @ s.X / 2}


@claim("r81b-td0-false", kind="id", sizes=SZ)
def td0_false(s):
    B, V = _data(s)
    f = _bad()
    return {"∂H/∂X = ∂<x², B>/∂X": s.gradient(lambda u: u.killing(f.grad(s, _xu(u)), B))[0]
            - s.gradient(lambda u: u.killing(_xu(u) @ _xu(u), B))[0]}
