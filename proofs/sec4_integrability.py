"""§4 Integrability of geodesic flows: the Jensen flows and their integrals."""
from __future__ import annotations

from stiefelsym import claim

SECTION = "4"


def H_jensen(s):
    """(EM) H_kappa = 1/2 <Phi, Phi> + kappa/2 <Psi, Psi>."""
    return s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2


@claim("jensen-integrals", paper=("ET", "so(n)+so(r)"), kind="pb",
       statement=r"\tfrac{d}{dt}\Phi=0,\quad \tfrac{d}{dt}\Psi=0\ \text{along the geodesic flow of } H_\kappa")
def momentum_maps_are_integrals_of_the_jensen_flows(s):
    """Theorem ET: Φ and Ψ are first integrals of the geodesic flows of the Jensen metrics H_κ, so Φ*(C∞(so(n))) and Ψ*(C∞(so(r))) lie in the algebra (so(n)+so(r)) of integrals."""
    flow = s.dirac_flow(H_jensen)
    return {
        "dPhi/dt": s.d(lambda t: t.Phi, flow),
        "dPsi/dt": s.d(lambda t: t.Psi, flow),
    }
