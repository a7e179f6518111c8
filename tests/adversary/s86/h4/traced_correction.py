"""A correction whose change text (the notation diff of its graph against the claim's) reads as another statement.

c1-potential: printed: the potential ½tr(XᵀAX) is conserved along the Neumann flow -- FALSE (d/dt = tr(XᵀAP) ≠ 0),
  fails: right.  Correction "V − K is conserved": its graph differentiates ½tr(XᵀAX) − ½tr(PᵀP) built from the
  claim's own s.X, s.A, s.P (closure constants: derivative 0), so it is proved -- right for the graph.  The report
  prints the change "… → ½tr(XᵀAX) − ½tr(PᵀP)" in the notation of the graph, i.e. the corrected statement reads
  d/dt(½tr(XᵀAX) − ½tr(PᵀP)) = 0 along the Neumann flow -- FALSE: d/dt(V − K) = 2 tr(XᵀAP) ≠ 0 (truth_numpy.py:
  dV/dt = tr(XᵀAP) = −dK/dt).
"""
from stiefelsym import admissible, claim


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("c1-potential", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n),
       fails_at=lambda n, r: r < n, erratum="the potential alone is not conserved")
def c1(s):
    """The potential ½ tr XᵀAX is conserved along the Neumann flow."""
    return {"dV/dt": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X) / 2, s.dirac_flow(H))}


@c1.claim.correction("V − K is conserved (the difference of potential and kinetic energy)")
def c1_fixed(s):
    return {"dV/dt": s.d(lambda t: s.tr(s.X.T @ s.A @ s.X) / 2 - s.tr(s.P.T @ s.P) / 2, s.dirac_flow(H))}
