"""Round 9 (note, IB; closed in round 10): the Dirac bracket (s.bracket) of a bracket whose inner function closes
over a value of the claim's point: the graph's rule refuses it, and the scene's own route evaluates the captured
value (a number of the point's field) against the inner bracket's reverse numbers over dual numbers over that
field.  Before round 10 every fixed-size method ended in a TypeError there (the lower operand took the higher
one for a constant of its own field); now a number of a field built over another's takes the other as its
constant, whichever operand comes first: the true Jacobi identity passes, {f, {g₀, h}} = 0 fails.  The twisted
bracket of the same functions is decided (s38b_nested_bracket_captures.py)."""
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
