from stiefelsym import admissible, claim

H = lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("nested-closure", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def nested(s):
    """Reads as d/dt(d/dt(½tr(XᵀAX))) = 0 along the Neumann flow (FALSE); the inner function closes over the outer
    function's point t.X, a constant for the inner derivative, so the graph is 0."""
    return {"dd": s.d(lambda t: t.d(lambda u: t.tr(t.X.T @ t.A @ t.X) / 2, t.dirac_flow(H)), s.dirac_flow(H))}
