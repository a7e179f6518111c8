"""Adversary of the unconstrained chart (f340a62): engine steps whose computation differs on and off T*V
(closed-form multipliers on V, solved systems off it), at r = 1 (where the right-reduced Cayley chart never
applies, so every graph that reads coordinates is tried on the unconstrained chart first) and in the metric
realization (always the unconstrained chart when coordinates are read)."""
from stiefelsym import admissible, claim, systems

S1 = [(2, 1), (3, 1)]


def H(t):
    return t.X[0, 0] * t.P[1, 0] + t.tr(t.P.T @ t.A @ t.P) + t.tr(t.X.T @ t.A @ t.X)


def H_captured(s):
    """A Hamiltonian with a constant captured from the enclosing scene: c = X11 d/d, d = tr(XᵀX) − r, 0/0
    on T*V.  Its gradient does not read c; the probe's closed-form flow (on V) never evaluates H's body,
    the unconstrained chart's solved flow does (where c = X11 is defined)."""
    d = s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    c = s.X[0, 0] * d / d

    def h(t):
        return t.tr(t.P.T @ t.A @ t.P) + c * t.tr(t.X.T @ t.X)
    return h


@claim("u-r1-dirac-tangent", kind="id", sizes=S1, statement="d/dt (X^T P + P^T X) = 0 along the Dirac flow")
def r1_dirac_tangent(s):
    """True (on every level set of the constraints, so also off T*V)."""
    f = s.dirac_flow(H)
    M = f.Xdot.T @ s.P + s.X.T @ f.Pdot
    return {"r": M + M.T}


@claim("u-r1-pi-closed", kind="id", sizes=S1, statement="Pi = sym(X^T H_P) at r = 1")
def r1_pi_closed(s):
    """True on T*V only (XᵀX = 1)."""
    fl = s.multiplier_flow(H)
    HX, HP = s.gradient(H)
    return {"r": fl.multipliers["Pi"] - (s.X.T @ HP + HP.T @ s.X) * s.q(1, 2)}


@claim("u-r1-bracket-antisym", kind="id", sizes=S1, statement="{F, G} + {G, F} = 0 (Dirac, entries)")
def r1_bracket_antisym(s):
    F = lambda t: t.X[0, 0] * t.P[0, 0]
    G = lambda t: t.X[1, 0] + t.P[1, 0] * t.P[1, 0]
    return {"r": s.bracket(F, G) + s.bracket(G, F)}


@claim("u-r1-bracket-casimir", kind="id", sizes=S1, statement="{X11, |X|^2} = 0 (Dirac)")
def r1_bracket_casimir(s):
    """True on T*V: |X|² is constant on T*V, so it is a Casimir of the Dirac bracket; off T*V too?"""
    return {"r": s.bracket(lambda t: t.X[0, 0], lambda t: t.tr(t.X.T @ t.X))}


@claim("u-r1-captured", kind="id", sizes=S1, statement="the Dirac flow of tr(PᵀAP) + c tr(XᵀX), c = X11 d/d")
def r1_captured(s):
    """Undefined on T*V (c = 0/0); the flow does not depend on c on T*V (tr XᵀX is a Casimir)."""
    f = s.dirac_flow(H_captured(s))
    g = s.dirac_flow(lambda t: t.tr(t.P.T @ t.A @ t.P))
    return {"r": f.Xdot[0, 0] - g.Xdot[0, 0]}


@claim("u-r1-captured-value", kind="id", sizes=S1, statement="c = X11 for c = X11 d/d (through a bracket)")
def r1_captured_value(s):
    """Undefined on T*V (c = 0/0), read only through the Hamiltonian whose bracket is taken."""
    h = H_captured(s)
    return {"r": s.bracket(lambda t: t.X[0, 0], h)}


@claim("u-r1-pairs-flow", kind="id", sizes=S1, statement="the pairs flow at (X, P) is the Dirac flow (entry H)")
def r1_pairs_flow(s):
    """True on T*V: systems.stiefel_pairs_flow at the scene's own point is the Dirac flow of H."""
    Hz = lambda t, z: z["x"][0, 0] * z["p"][1, 0] + t.tr(z["p"].T @ t.A @ z["p"])
    fl = systems.stiefel_pairs_flow(s, Hz, {"x": s.X, "p": s.P}, [("x", "p")])
    g = s.dirac_flow(lambda t: t.X[0, 0] * t.P[1, 0] + t.tr(t.P.T @ t.A @ t.P))
    return {"x": fl["x"] - g.Xdot, "p": fl["p"] - g.Pdot}


@claim("u-metric-entry-flow", kind="id", sizes=admissible(n_max=3), realization="metric",
       statement="X^T A^-1 Xdot + Xdot^T A^-1 X ... the metric Dirac flow is tangent (entries)")
def metric_entry_flow(s):
    """True: d/dt(XᵀX) = 0 along the metric Dirac flow (read entrywise)."""
    f = s.dirac_flow(H)
    M = s.X.T @ f.Xdot
    return {"r": M[0, 0] + M[0, 0]}


@claim("u-metric-entry-false", kind="id", sizes=admissible(n_max=3), realization="metric",
       statement="false: (X^T Xdot)_11 = (X^T H_P)_11 for the metric Dirac flow")
def metric_entry_false(s):
    f = s.dirac_flow(H)
    HX, HP = s.gradient(H)
    return {"r": (s.X.T @ f.Xdot)[0, 0] - (s.X.T @ HP)[0, 0]}
