"""Round 6: brackets.poisson_map_residual calls the map and the covectors a, b on the scenes of the two functions
whose bracket it takes and on the claim's scene: a covector that is G in the bracket and 2G on the right side makes
the doubled momentum map 2Φ a "Poisson map" into (so(n), Lie–Poisson)."""
from stiefelsym import admissible, claim
from stiefelsym.brackets import SO_N, dirac, lie_poisson, poisson_map_residual


class Covector:
    """G on its first call, 2G afterwards."""

    def __init__(self, name):
        self.name, self.calls = name, 0

    def __call__(self, t):
        self.calls += 1
        G = SO_N.project(t.generic(self.name, "n", "n"))
        return G if self.calls == 1 else G * 2


@claim("adv-s36-pmap-stateful-covector", kind="pb", sizes=admissible(n_max=3))
def doubled(s):
    """False: the doubled momentum map 2Φ = 2(PXᵀ − XPᵀ) is a Poisson map into (so(n), Lie–Poisson)."""
    M = lambda t: (t.P @ t.X.T - t.X @ t.P.T) * 2   # noqa: E731
    return {"pmap": poisson_map_residual(s, dirac, M, lie_poisson(SO_N), Covector("a"), lambda t: SO_N.project(t.generic("b", "n", "n")))}


@claim("adv-s36-pmap-control", kind="pb", sizes=admissible(n_max=3))
def control(s):
    """False: the doubled momentum map is a Poisson map (one covector)."""
    M = lambda t: (t.P @ t.X.T - t.X @ t.P.T) * 2   # noqa: E731
    return {"pmap": poisson_map_residual(s, dirac, M, lie_poisson(SO_N), lambda t: SO_N.project(t.generic("a", "n", "n")),
                                         lambda t: SO_N.project(t.generic("b", "n", "n")))}


@claim("adv-s36-pmap-true", kind="pb", sizes=admissible(n_max=3))
def true(s):
    """True (up to sign): Φ = PXᵀ − XPᵀ is a Poisson map into (so(n), ±Lie–Poisson)."""
    M = lambda t: (t.P @ t.X.T - t.X @ t.P.T)   # noqa: E731
    r1 = poisson_map_residual(s, dirac, M, lie_poisson(SO_N), lambda t: SO_N.project(t.generic("a", "n", "n")), lambda t: SO_N.project(t.generic("b", "n", "n")))
    r2 = poisson_map_residual(s, dirac, M, lie_poisson(SO_N, -1), lambda t: SO_N.project(t.generic("a", "n", "n")), lambda t: SO_N.project(t.generic("b", "n", "n")))
    return {"pmap": r1 * r2}


@claim("adv-s36-pmap-captured-true", kind="pb", sizes=admissible(n_max=3))
def captured_true(s):
    """True (up to sign): Φ is a Poisson map, its covectors captured from the claim's scene."""
    M = lambda t: (t.P @ t.X.T - t.X @ t.P.T)   # noqa: E731
    A, B = SO_N.project(s.generic("a", "n", "n")), SO_N.project(s.generic("b", "n", "n"))
    r1 = poisson_map_residual(s, dirac, M, lie_poisson(SO_N), lambda t: A, lambda t: B)
    r2 = poisson_map_residual(s, dirac, M, lie_poisson(SO_N, -1), lambda t: A, lambda t: B)
    return {"pmap": r1 * r2}
