"""A value of a function handed to the scene (its own X, a fresh letter of the function's scene) kept in a
module list and used by the claim outside the function, after the gradient, the derivative or the bracket.
The graph holds a node of the function's body where the claim's point is meant."""
from stiefelsym import admissible, claim

_LEAK = []


def _F(t):
    _LEAK.append(t.X)
    return t.tr(t.X.T @ t.A @ t.X)


def _H(t):
    return t.tr(t.P.T @ t.P) / 2


@claim("adv-escaped-gradient", kind="id", sizes=admissible(n_max=3), statement="(the function's X) = P")
def escaped_gradient(s):
    """False whatever the escaped value stands for (X or a fresh point): X - P, or a letter minus P."""
    _LEAK.clear()
    s.gradient(_F)
    return {"r": _LEAK[-1] - s.P}


@claim("adv-escaped-derivative", kind="id", sizes=admissible(n_max=3), statement="(the function's X) = P")
def escaped_derivative(s):
    """False."""
    _LEAK.clear()
    s.d(_F, s.dirac_flow(_H))
    return {"r": _LEAK[-1] - s.P}


@claim("adv-escaped-bracket", kind="id", sizes=admissible(n_max=3), statement="{F, H} = 2 tr(X'^T A P), X' escaped")
def escaped_bracket(s):
    """{tr(X^T A X), |P|^2/2} = 2 tr(X^T A P) restricted to T*V is not this (the Dirac bracket has a multiplier
    term); false with X' = X."""
    _LEAK.clear()
    b = s.bracket(_F, _H)
    return {"r": b - 2 * s.tr(_LEAK[-1].T @ s.A @ s.P) + s.tr(s.X.T @ s.P)}
