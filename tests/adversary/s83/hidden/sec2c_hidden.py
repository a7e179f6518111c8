"""h3 hidden statements, §2: (scalar) the r(r+1) constraints have independent differentials at EVERY point,
written naturally as a rank at every point of the Jacobian."""
from stiefelsym import Rank, admissible, claim


def constraints(t):
    return [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X]


@claim("h3-constraints-rank-everywhere", kind="dim", section="2", sizes=admissible(4))
def constraints_rank_everywhere(s):
    """(scalar): d(XᵀX) (δX) = δXᵀX + XᵀδX takes every symmetric value (δX = XS/2), and with δX = 0,
    d(XᵀP + PᵀX)(δP) = XᵀδP + δPᵀX takes every symmetric value (δP = XT/2): the differential of the r(r+1) scalar
    constraints (upper triangles) is onto at every point of T*V, so the Jacobian has rank r(r+1) everywhere."""
    r = int(s.r)
    return {"rank dF": Rank(s.mat(s.jacobian(constraints, symmetric=True)), r * (r + 1), generic=False)}


@claim("h3-constraints-rank-everywhere-twin", kind="dim", section="2", sizes=admissible(4))
def constraints_rank_everywhere_twin(s):
    """FALSE twin: rank r(r+1) + 1."""
    r = int(s.r)
    return {"rank dF": Rank(s.mat(s.jacobian(constraints, symmetric=True)), r * (r + 1) + 1, generic=False)}
