"""A function of an n×r matrix with its gradient: <a, b> = −½ tr(ab) pairs an n×r point with an r×n gradient, so
k(y) = <yᵀ, y> = −½ tr(yᵀy) has dk(δ) = −tr(yᵀδ) = <2yᵀ, δ>, ∇k(y) = 2yᵀ.  The check's zero had the point's shape,
and the sum G + zero was refused for every such function.
  s81-nr-true:            ∇k(X) = 2Xᵀ                    TRUE
  s81-nr-false:           ∇k(X) = Xᵀ                     FALSE
  s81-nr-wrong-declared:  k declared with gradient yᵀ    refused (not the value's gradient)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction
SZ = admissible(n_min=3, n_max=3)
def _k(g=2):
    return MatrixFunction(lambda t, y: t.killing(y.T, y), lambda t, y: y.T * g, "k")
@claim("s81-nr-true", kind="id", sizes=SZ)
def t_(s):
    return {"∇k(X) = 2Xᵀ": _k().grad(s, s.X) - s.X.T * 2}
@claim("s81-nr-false", kind="id", sizes=SZ)
def f_(s):
    return {"∇k(X) = Xᵀ": _k().grad(s, s.X) - s.X.T}
@claim("s81-nr-wrong-declared", kind="id", sizes=SZ)
def w_(s):
    return {"∇k(X) = Xᵀ (declared)": _k(1).grad(s, s.X) - s.X.T}
