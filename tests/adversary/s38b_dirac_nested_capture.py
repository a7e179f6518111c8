"""Round 9 (note): the Dirac bracket (s.bracket) of a bracket whose inner function closes over a value of the
claim's point: the graph's rule refuses it, and the scene's own route then meets the captured value of the
degree-tracking evaluation (values paired with their degrees) inside its dual numbers: every fixed-size method
ends in a TypeError, the true statement as the false one (never a wrong verdict).  The twisted bracket of the same
functions is decided (s38b_nested_bracket_captures.py)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=3, r_min=2, r_max=2)


def fns(s):
    return (lambda t: t.killing(t.Phi, t.xi),
            lambda t: t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.generic("U", "n", "r").T @ t.P))


@claim("adv-s38b-dirac-jacobi-captured", kind="id", sizes=SZ)
def dirac_jacobi_captured(s):
    """The Jacobi identity of the Dirac bracket for f, g₀ = tr(X₀ᵀ t.X) (X₀ the claim's X) and h (true)."""
    f, h = fns(s)
    X0 = s.X
    g0 = lambda t: t.tr(X0.T @ t.X)                            # noqa: E731
    B = lambda u, v: (lambda t: t.bracket(u, v))               # noqa: E731
    return {"J": s.bracket(f, B(g0, h)) + s.bracket(g0, B(h, f)) + s.bracket(h, B(f, g0))}


@claim("adv-s38b-dirac-captured-zero", kind="id", sizes=SZ)
def dirac_captured_zero(s):
    """{f, {g₀, h}} = 0 (false)."""
    f, h = fns(s)
    X0 = s.X
    g0 = lambda t: t.tr(X0.T @ t.X)                            # noqa: E731
    return {"d": s.bracket(f, lambda t: t.bracket(g0, h))}
