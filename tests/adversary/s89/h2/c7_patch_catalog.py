"""Class 7/4: a claims file that, when imported, rebinds a module global of the catalog (proofs.sec3_geodesic_flows.H_euclidean,
H_E = ½tr PᵀP, to tr PᵀP) and the catalog claim euclidean-flow (TRUE: Ẋ = P, Ṗ = −XPᵀP) is run beside it.
A `fails` of euclidean-flow would be a wrong verdict of a catalog claim.  The file's own claim c7p-own is TRUE
(XᵀX = I_r), a carrier."""
import proofs.sec3_geodesic_flows as m
from stiefelsym import admissible, claim

m.H_euclidean = lambda t: t.tr(t.P.T @ t.P)


@claim("c7p-own", kind="id", sizes=admissible(n_max=3))
def own(s):
    """TRUE: XᵀX = I_r."""
    return {"r": s.X.T @ s.X - s.Ir}
