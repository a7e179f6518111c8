def flow_big_neumann(s):
    """The Dirac flow of ½tr(PᵀP) + ½(10¹² + 39) tr(XᵀAX)."""
    return s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) * (10**12 + 39) / 2)
