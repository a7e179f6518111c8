"""Right-reduced chart: a coordinate of R^r read only inside a function handed to the scene."""
from stiefelsym import admissible, claim


def H01(t):
    return (t.X.T @ t.A @ t.X)[0, 1]


@claim("h2r-d-entry", kind="id", sizes=admissible(n_min=2, r_min=2, n_max=3))
def d_entry(s):
    """False: 2 (X^T A X)_{12} a_1 = 0 (true at X = I)."""
    return {"r": s.d(H01, {"X": s.X}) * s.A[0, 0]}


@claim("h2r-d-entry-true", kind="id", sizes=admissible(n_min=2, r_min=2, n_max=3))
def d_entry_true(s):
    """True: d/de H01(X + eX) - 2 H01 = 0."""
    return {"r": (s.d(H01, {"X": s.X}) - 2 * H01(s)) * s.A[0, 0]}


@claim("h2r-grad-entry", kind="id", sizes=admissible(n_min=2, r_min=2, n_max=3))
def grad_entry(s):
    """False: tr(X^T grad_X H01) a_1 = 0."""
    HX, HP = s.gradient(H01)
    return {"r": s.tr(s.X.T @ HX) * s.A[0, 0]}


@claim("h2r-flow-entry", kind="id", sizes=admissible(n_min=2, r_min=2, n_max=3))
def flow_entry(s):
    """False: along the Dirac flow of H = tr P^T P/2 + (X^T A X)_{12}, d tr(X^T A X)/dt ... ."""
    fl = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + H01(t))
    return {"r": s.d(lambda t: t.tr(t.P.T @ t.A @ t.X), fl) * s.A[0, 0]}


@claim("h2r-bracket-entry", kind="id", sizes=admissible(n_min=2, r_min=2, n_max=3))
def bracket_entry(s):
    """False: {H01, tr(X^T A X)/2... } a_1 = 0."""
    return {"r": s.bracket(H01, lambda t: t.tr(t.P.T @ t.P) / 2) * s.A[0, 0]}
