"""A graph mutant's description leaves out one of the places the change is made at.

The tracer shares one node per leaf read inside a function (hash-consing), so the letter mutant P -> X of
the P read in `t.X.T @ t.P + t.P.T @ t.X` changes both terms: XᵀP + PᵀX -> XᵀX + XᵀX, whose derivative along
any flow that keeps XᵀX is 0 (TRUE, rightly "equivalent").  `mutate` describes it as "in sym: XᵀP → XᵀX",
that is d/dt(XᵀX + PᵀX) = 0, which is FALSE for this H (not O(r)-invariant: Ψ is not conserved):
`s76-described-mutant` below fails under every method."""
from stiefelsym import claim

SZ = [(3, 2)]


def H(t):
    """A Hamiltonian that is not invariant under O(r) on the right (it reads entries)."""
    return t.tr(t.P.T @ t.P) / 2 + t.X[0, 0] * t.P[1, 1] + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s76-tangent", kind="id", sizes=SZ)
def tangent(s):
    """The Dirac flow of H keeps XᵀP + PᵀX (true)."""
    return {"sym": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, s.dirac_flow(H))}


@claim("s76-described-mutant", kind="id", sizes=SZ)
def described_mutant(s):
    """FALSE: the mutant as described, d/dt(XᵀX + PᵀX) = 0."""
    return {"sym": s.d(lambda t: t.X.T @ t.X + t.P.T @ t.X, s.dirac_flow(H))}


@claim("s76-actual-mutant", kind="id", sizes=SZ)
def actual_mutant(s):
    """TRUE: the mutant as made, d/dt(XᵀX + XᵀX) = 0."""
    return {"sym": s.d(lambda t: t.X.T @ t.X + t.X.T @ t.X, s.dirac_flow(H))}
