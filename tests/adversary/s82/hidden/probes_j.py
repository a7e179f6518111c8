"""s82 hidden (h2): Jacobi identity of the twisted Dirac bracket for a field strength that depends on the point,
F = tr(PᵀP)·η (skew by construction, accepted).  ω + ε π*(...) is then not closed for n ≥ 3
(d(f η₁₂ de₁∧de₂) = η₁₂ df∧de₁∧de₂, df = 2Σ p·dp, nonzero on T*V(3, 2)), so the Jacobiator should not vanish at
n = 3; at n = 2, de₁∧de₂ vanishes on the 1-dimensional V(2, 2) and it holds.  Control: constant F = c·η (closed)."""
from stiefelsym import claim, twisted

SIZES = [(2, 2), (3, 2)]


def _fgh(s):
    return (lambda t: t.killing(t.Phi, t.xi),
            lambda t: t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P),
            lambda t: t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.generic("U", "n", "r").T @ t.P))


def _jacobi(s, Ffun):
    f, g, h = _fgh(s)
    br = lambda t, F, G: twisted.bracket(t, F, G, Ffun(t))
    b = lambda F, G: (lambda t: br(t, F, G))
    return {"Jacobi": br(s, f, b(g, h)) + br(s, g, b(h, f)) + br(s, h, b(f, g))}


@claim("p82j-jacobi-pointwise-F", kind="pb", sizes=SIZES, fails_at=lambda n, r: n >= 3,
       erratum="a non-closed form: Jacobi fails for n >= 3")
def jacobi_pointwise(s):
    """Jacobi for F = tr(PᵀP)η (expected to fail at n = 3)."""
    return _jacobi(s, lambda t: t.tr(t.P.T @ t.P) * t.eta)


@claim("p82j-jacobi-constant-F", kind="pb", sizes=SIZES)
def jacobi_constant(s):
    """Jacobi for F = c·η (closed; holds)."""
    return _jacobi(s, lambda t: t.scalar("c") * t.eta)
