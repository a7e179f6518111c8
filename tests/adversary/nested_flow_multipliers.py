"""A Hamiltonian that holds a flow (a Dirac bracket taken inside it): the free scene solves the inner flow's
multipliers modulo the constraints, which changes the Hamiltonian off T*V.  Its Dirac flow stands (true claim);
its Lagrange multipliers, which depend on it off T*V, do not (false claim: they differ from those of the
Hamiltonian written out on T*V)."""
from stiefelsym import admissible, claim

ALL = admissible(n_max=4, n_min=2)


@claim("adv-nested-multipliers", kind="id", sizes=ALL)
def nested_multipliers(s):
    """The multipliers of H1 = {tr(X^T A X), tr(P^T P)/2} (a bracket inside) and of H2 = 2 tr(X^T A P) agree (false)."""
    H1 = lambda u: u.bracket(lambda w: w.tr(w.X.T @ w.A @ w.X), lambda w: w.tr(w.P.T @ w.P) / 2)
    H2 = lambda u: 2 * u.tr(u.X.T @ u.A @ u.P)
    f1, f2 = s.multiplier_flow(H1), s.multiplier_flow(H2)
    return {"Pi": f1.multipliers["Pi"] - f2.multipliers["Pi"], "Lambda": f1.multipliers["Lambda"] - f2.multipliers["Lambda"]}


@claim("adv-nested-dirac-flow", kind="id", sizes=ALL)
def nested_dirac_flow(s):
    """The Dirac flows of H1 and H2 (equal on T*V, so their Dirac flows agree: true)."""
    H1 = lambda u: u.bracket(lambda w: w.tr(w.X.T @ w.A @ w.X), lambda w: w.tr(w.P.T @ w.P) / 2)
    H2 = lambda u: 2 * u.tr(u.X.T @ u.A @ u.P)
    f1, f2 = s.dirac_flow(H1), s.dirac_flow(H2)
    return {"Xdot": f1.Xdot - f2.Xdot, "Pdot": f1.Pdot - f2.Pdot}
