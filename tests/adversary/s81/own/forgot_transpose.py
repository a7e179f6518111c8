"""The stop's last own attempt: a careless user's gradient of a function of an n×r matrix written with the point's
shape (2y instead of 2yᵀ for k(y) = <yᵀ, y> = −½ tr(yᵀy), whose gradient for <a, b> = −½ tr(ab) is 2yᵀ), then used
in a bracket-like pairing that reads it back transposed.  At r = n both shapes are n×n numerically, but the types
differ; the declared gradient is not the value's: refused, never a verdict.
  s81-ft-false: <∇k(X)ᵀ, V> = 0 for a generic V (n×r)     FALSE (∇k(X)ᵀ = 2X: <2X... > ≠ 0)
  s81-ft-true:  the same with the right gradient, <∇k(X), Vᵀ>... = <2Xᵀ, ...>  TRUE identity ∇k(X) − 2Xᵀ = 0
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_min=2, n_max=3)


@claim("s81-ft-false", kind="id", sizes=SZ)
def ft_false(s):
    k = MatrixFunction(lambda t, y: t.killing(y.T, y), lambda t, y: y * 2, "k")
    return {"∇k(X) − 2X = X": k.grad(s, s.X) - s.X * 2 - s.X}


@claim("s81-ft-true", kind="id", sizes=SZ)
def ft_true(s):
    k = MatrixFunction(lambda t, y: t.killing(y.T, y), lambda t, y: y.T * 2, "k")
    return {"∇k(X) = 2Xᵀ": k.grad(s, s.X) - s.X.T * 2}
