"""s88h1 claims 2: the Dirac bracket (Dirac_bracket) as a Poisson bracket whose restriction to T*V depends only on
the restrictions of the functions (§2, after (Dirac_bracket)).

 s88h1-dirac-jacobi (TRUE): {{f,g},h} + {{g,h},f} + {{h,f},g} = 0 for f = Φ_ξ, g = tr(B PᵀP), h = tr(UᵀP).
 s88h1-dirac-jacobi-twin (FALSE where the cyclic terms do not vanish): {{f,g},h} + {{g,h},f} − {{h,f},g} = 0.
 s88h1-dirac-leibniz (TRUE): {f, g h} = {f, g} h + g {f, h}, f = tr(UᵀP), g = tr(WᵀX), h = tr(BPᵀP).
 s88h1-dirac-leibniz-twin (FALSE): {f, g h} = {f, g} h − g {f, h}.
 s88h1-dirac-restriction (TRUE): {f + tr(S(XᵀX − I)) + tr(T(XᵀP + PᵀX)), g} = {f, g} on T*V
   (Dirac bracket; f = tr(UᵀP), g = tr(WᵀP), S, T symmetric generic).
 s88h1-dirac-restriction-twin (FALSE): the same with the canonical bracket {·,·}_0.
"""
from stiefelsym import admissible, claim

SMALL = admissible(n_max=3)


def fns(s):
    U = s.generic("U", "n", "r")
    W = s.generic("W", "n", "r")
    B = s.generic("B", "r", "r")
    f = lambda t: t.killing(t.Phi, s.xi)  # noqa: E731
    g = lambda t: t.tr(B @ t.P.T @ t.P)  # noqa: E731
    h = lambda t: t.tr(U.T @ t.P)  # noqa: E731
    return U, W, B, f, g, h


def jac(s, sign):
    U, W, B, f, g, h = fns(s)
    t1 = s.bracket(lambda t: t.bracket(f, g), h)
    t2 = s.bracket(lambda t: t.bracket(g, h), f)
    t3 = s.bracket(lambda t: t.bracket(h, f), g)
    return {"jacobi": t1 + t2 + sign * t3}


@claim("s88h1-dirac-jacobi", kind="pb", section="2", sizes=SMALL)
def jacobi(s):
    """Jacobi identity of the Dirac bracket (TRUE)."""
    return jac(s, 1)


@claim("s88h1-dirac-jacobi-twin", kind="pb", section="2", sizes=SMALL)
def jacobi_twin(s):
    """one cyclic term with the wrong sign (FALSE)."""
    return jac(s, -1)


def leib(s, sign):
    U, W, B, _, _, _ = fns(s)
    f = lambda t: t.tr(U.T @ t.P)  # noqa: E731
    g = lambda t: t.tr(W.T @ t.X)  # noqa: E731
    h = lambda t: t.tr(B @ t.P.T @ t.P)  # noqa: E731
    gh = lambda t: g(t) * h(t)  # noqa: E731
    return {"leibniz": s.bracket(f, gh) - s.bracket(f, g) * h(s) - sign * g(s) * s.bracket(f, h)}


@claim("s88h1-dirac-leibniz", kind="pb", section="2", sizes=SMALL)
def leibniz(s):
    """Leibniz rule (TRUE)."""
    return leib(s, 1)


@claim("s88h1-dirac-leibniz-twin", kind="pb", section="2", sizes=SMALL)
def leibniz_twin(s):
    """Leibniz with a wrong sign (FALSE)."""
    return leib(s, -1)


def restr(s, br):
    U, W, _, _, _, _ = fns(s)
    S = s.generic("S", "r", "r", "sym")
    T = s.generic("T", "r", "r", "sym")
    f = lambda t: t.tr(U.T @ t.P)  # noqa: E731
    f2 = lambda t: t.tr(U.T @ t.P) + t.tr(S @ (t.X.T @ t.X - t.Ir)) + t.tr(T @ (t.X.T @ t.P + t.P.T @ t.X))  # noqa: E731
    g = lambda t: t.tr(W.T @ t.P)  # noqa: E731
    return {"restriction": br(f2, g) - br(f, g)}


@claim("s88h1-dirac-restriction", kind="pb", section="2", sizes=SMALL)
def restriction(s):
    """Dirac bracket depends on restrictions only (TRUE)."""
    return restr(s, s.bracket)


@claim("s88h1-dirac-restriction-twin", kind="pb", section="2", sizes=SMALL)
def restriction_twin(s):
    """the canonical bracket does too (FALSE)."""
    return restr(s, s.canonical_bracket)
