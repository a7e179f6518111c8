"""§3 Geodesic flows: Euclidean, submersion, normal, Jensen (Einstein) and
SO(r)-invariant metrics on V(n, r)."""
from __future__ import annotations

from stiefelsym import Count, Rank, admissible, block, claim, comm

SECTION = "3"


# -- Hamiltonians of the section ---------------------------------------------

def H_euclidean(s):
    """(Euclidean) H_E = 1/2 tr(P^T P)."""
    return s.tr(s.P.T @ s.P) / 2


def H_normal(s):
    """(normal_metric) H_0 = 1/2 <Phi, Phi>."""
    return s.killing(s.Phi, s.Phi) / 2


def H_jensen(s):
    """(EM) H_kappa = 1/2 <Phi, Phi> + kappa/2 <Psi, Psi>."""
    return s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2


def H_submersion(s):
    """(submersion_metric) H_AA = 1/2 <AA Phi, Phi> for a generic symmetric operator AA on so(n)."""
    return s.killing(s.sym_operator("AA")(s.Phi), s.Phi) / 2


def H_metric_A(s):
    """H_A = 1/2 tr(P^T A^{-1} P)."""
    return s.tr(s.P.T @ s.Ainv @ s.P) / 2


# -- the Euclidean metric ------------------------------------------------------

@claim("euclidean-flow", paper=("Euclidean", "Euclidean_XP"), kind="id",
       statement=r"H_E=\tfrac12\tr(P^TP):\quad \dot X=P,\ \dot P=-XP^TP,\quad \Lambda=-\dot X^T\dot X")
def euclidean_geodesic_flow(s):
    """The Dirac flow of H_E = ½tr(PᵀP) is Ẋ = P, Ṗ = −XPᵀP; in Lagrange form Ẍ = XΛ with Λ = −ẊᵀẊ."""
    flow = s.dirac_flow(H_euclidean)
    mult = s.multiplier_flow(H_euclidean)
    return {
        "dX/dt": flow.Xdot - s.P,
        "dP/dt": flow.Pdot - (-s.X @ s.P.T @ s.P),
        "Lambda": mult["Lambda"] - (-(flow.Xdot.T @ flow.Xdot)),
        "Pi": mult["Pi"],
    }


@claim("euclidean-invariance", paper=("Euclidean_XP",), kind="id",
       statement=r"\tfrac{d}{dt}(X^TX)=0,\ \tfrac{d}{dt}(X^TP+P^TX)=0 \text{ along } \dot X=P,\ \dot P=-XP^TP")
def euclidean_flow_keeps_the_cotangent_bundle(s):
    """The printed Euclidean flow Ẋ = P, Ṗ = −XPᵀP is tangent to T*V (it keeps the constraints)."""
    printed = {"X": s.P, "P": -s.X @ s.P.T @ s.P}
    return {
        "d(X^T X)/dt": s.d(lambda t: t.X.T @ t.X, printed),
        "d(X^T P + P^T X)/dt": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, printed),
    }
