# ruff: noqa
"""s72 probes, third set: 'not' claims whose residual vanishes on T*V but not off it (must fail), and a rank
claim with a kernel certificate that is not a kernel (must not be used)."""
from stiefelsym import Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

ALL = lambda n, r: True


@claim("p72-not-constraint", kind="not", expect="nonzero", sizes=admissible(n_max=3), fails_at=ALL,
       erratum="probe: XᵀP + PᵀX vanishes on T*V")
def not_constraint(s):
    """'XᵀP + PᵀX ≠ 0' — false on T*V (zero there), nonzero off it."""
    return {"X^TP + P^TX": s.X.T @ s.P + s.P.T @ s.X}


@claim("p72-not-trace-xtp", kind="not", expect="nonzero", sizes=admissible(n_max=3), fails_at=ALL,
       erratum="probe: tr XᵀP = 0 on T*V")
def not_trace(s):
    """'tr(XᵀP) ≠ 0' — false on T*V (XᵀP is skew there)."""
    return {"tr X^TP": s.tr(s.X.T @ s.P)}


@claim("p72-not-xtx", kind="not", expect="nonzero", sizes=admissible(n_max=3), fails_at=ALL,
       erratum="probe: XᵀX = I on V")
def not_xtx(s):
    """'XᵀX − I ≠ 0' — false on V."""
    return {"X^TX - I": s.X.T @ s.X - s.Ir}


@claim("p72-rank-bogus-kernel", kind="dim", sizes=admissible(n_max=5, n_min=3, r_max=1),
       fails_at=ALL, erratum="probe: rank one below 2(n − 2), with a 'kernel' that is not one")
def rank_bogus_kernel(s):
    """rank ad_Φ = 2(n − 2) − 1 at r = 1, with kernel= the first 2(n−2)... columns of the identity (not a kernel)."""
    n = int(s.n)
    m = n * (n - 1) // 2
    M = matrix_of(s, lambda xi: comm(xi, s.Phi), so_basis(s, "n"), "skew")
    d = m - (2 * (n - 2) - 1)
    K = s.mat([[1 if i == j else 0 for j in range(d)] for i in range(m)], ("?", "?"))
    return {"rank": Rank(M, 2 * (n - 2) - 1, kernel=K)}


@claim("p72-false-equivariance-reason", kind="id", sizes=admissible(n_max=3, n_min=2), fails_at=ALL,
       equivariance="a false reason: the residual is claimed covariant although it reads an entry of X",
       erratum="probe: X[1, 0] = 0 holds at X0 = (E1 ... Er) only")
def false_equivariance(s):
    """X₂₁ = 0: true at X₀ = (E₁ … E_r), false at a generic point of V; a user's equivariance= reason must not be
    relied on."""
    return {"X[1,0]": s.X[1, 0]}
