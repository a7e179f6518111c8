"""Round 9: brackets of magnetic brackets on the dimension-free scene, {f, G}_F with G(t) = {g, h}_F'(t), whose
inner functions or field strength close over a value of the claim's point.  At fixed sizes such a value is a
constant of G (only t moves); the free algebra's rule ({f, G} = -dG(X_f), G a value at the scene's own point,
differentiated by the derivation of the free algebra) and the scene's own twisted flow inside a function (its
field strength renamed with the point) moved it with the point: false statements proved for every n, r."""
from stiefelsym import admissible, claim, twisted

SZ = admissible(n_max=3, n_min=2, r_min=2, r_max=2)


def fns(s):
    """⟨Φ, ξ⟩, tr(GPᵀP), ½tr(XᵀAX) + tr(UᵀP) (the catalog's Jacobi test functions)."""
    return (lambda t: t.killing(t.Phi, t.xi),
            lambda t: t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P),
            lambda t: t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.generic("U", "n", "r").T @ t.P))


def c_eta(t):
    """tr(XᵀAX)·η: an element of so(r) that moves with t's point."""
    return t.tr(t.X.T @ t.A @ t.X) * t.eta


@claim("adv-s38b-jacobi-captured-F", kind="id", sizes=SZ)
def jacobi_captured_field_strength(s):
    """The Jacobi identity of the twisted bracket for the field strength F = c·η frozen at the claim's point
    (a constant element of so(r) for every bracket: true)."""
    f, g, h = fns(s)
    F = c_eta(s)
    b = lambda u, v: (lambda t: twisted.bracket(t, u, v, F=F))     # noqa: E731
    return {"J": twisted.bracket(s, f, b(g, h), F=F) + twisted.bracket(s, g, b(h, f), F=F)
            + twisted.bracket(s, h, b(f, g), F=F)}


@claim("adv-s38b-captured-F-is-moving-F", kind="id", sizes=SZ)
def captured_field_strength_moves(s):
    """{f, {g, h}_F}_F with the inner F = c·η frozen at the claim's point equals the one where the inner F is
    c(t)·η, moving with the point (false: they differ by the derivative of c along the flow of f)."""
    f, g, h = fns(s)
    F = c_eta(s)
    frozen = lambda t: twisted.bracket(t, g, h, F=F)          # noqa: E731
    moving = lambda t: twisted.bracket(t, g, h, F=c_eta(t))   # noqa: E731
    return {"d": twisted.bracket(s, f, frozen, F=F) - twisted.bracket(s, f, moving, F=F)}


@claim("adv-s38b-captured-g-zero", kind="id", sizes=SZ)
def captured_inner_function(s):
    """{f, {g₀, h}_η}_η = 0 for g₀(t) = tr(X₀ᵀ t.X), X₀ the claim's X (false: {g₀, h}_η vanishes at X₀, whose
    gradient X₀ is normal to V there, but not at the points along the flow of f)."""
    f, _, h = fns(s)
    X0 = s.X
    g0 = lambda t: t.tr(X0.T @ t.X)                           # noqa: E731
    return {"d": twisted.bracket(s, f, lambda t: twisted.bracket(t, g0, h, F=t.eta), F=s.eta)}


@claim("adv-s38b-jacobi-eta", kind="id", sizes=SZ)
def jacobi_eta(s):
    """The control: the Jacobi identity for the constant field strength η of the function's scene (true)."""
    f, g, h = fns(s)
    b = lambda u, v: (lambda t: twisted.bracket(t, u, v, F=t.eta))     # noqa: E731
    return {"J": twisted.bracket(s, f, b(g, h), F=s.eta) + twisted.bracket(s, g, b(h, f), F=s.eta)
            + twisted.bracket(s, h, b(f, g), F=s.eta)}
