"""The check on the claim's scene s inside the function of s.d, with the point AND the declared gradient computed
inside the function from s alone (s.X s.Xᵀ: no value of t, no value captured from outside), the value closing over
the derivative's scene t: do the evaluator's lifts still mark x and G as the derivative's numbers, so that
`_refuse_foreign_numbers` sees them?  (If x and G stayed s's own numbers, the check on s would compare the value's
gradient, a dual number, with G on s's field.)
  F_t(y) = <y, X_t X_tᵀ>, declared ∇ = s.X s.Xᵀ (right at ε = 0 only); F_t.grad(s, XXᵀ) means ∇F_t = X_t X_tᵀ, so
  d/dε F_t.grad(s, XXᵀ) = VXᵀ + XVᵀ.
  r81b-ic-false: d = 0               FALSE
  r81b-ic-true:  d = VXᵀ + XVᵀ       TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _d(s, V):
    def body(t):
        F = MatrixFunction(lambda u, y: u.killing(y, t.X @ t.X.T), lambda u, y: s.X @ s.X.T, "F_t")
        return F.grad(s, s.X @ s.X.T)
    return s.d(body, {"X": V})


@claim("r81b-ic-false", kind="id", sizes=SZ)
def ic_false(s):
    V = s.fresh("n", "r")
    return {"d = 0": _d(s, V)}


@claim("r81b-ic-true", kind="id", sizes=SZ)
def ic_true(s):
    V = s.fresh("n", "r")
    return {"d = VXᵀ + XVᵀ": _d(s, V) - V @ s.X.T - s.X @ V.T}
