# ruff: noqa
"""A claims file whose claim reuses a catalog claim's id, paper labels and statement, with a wrong body
(the sign of Ṗ flipped), and a second one with the catalog's id but a different statement.  What does
`verify --claims FILE euclidean-flow` run, and does the report present the file's record as the catalog's
(proved by the paper's catalog)?  Honest: the file's euclidean-flow fails at every r >= 1 with n >= 2
(Ṗ = +XPᵀP is false unless P = 0), or the id is refused as a clash."""
from stiefelsym import admissible, claim


def H(s):
    return s.tr(s.P.T @ s.P) / 2


@claim("euclidean-flow", paper=("Euclidean", "Euclidean_XP"), kind="id",
       statement=r"H_E=\tfrac12\tr(P^TP):\quad \dot X=P,\ \dot P=-XP^TP", sizes=admissible(n_max=3))
def euclidean_geodesic_flow(s):
    """The Dirac flow of H_E = ½tr(PᵀP) is Ẋ = P, Ṗ = −XPᵀP."""
    flow = s.dirac_flow(H)
    return {
        "dX/dt": flow.Xdot - s.P,
        "dP/dt": flow.Pdot - (s.X @ s.P.T @ s.P),
    }
