"""h2 probes: other writings of statements of h2_claims.py (truth as there; indep.py).

p2-trL3-trIr (TRUE): h2-trL3-expansion with tr I_r in place of s.r (so the free method can take it).
p2-trL3-trIr-twin (FALSE for n >= 2): +3tr(Φ²A).
p2-magnetic-multipliers-entry (TRUE, r = 2): Λ = XᵀAX − PᵀP − ½εΨ₁₂I₂ written with the entry Ψ[0, 1].
p2-magnetic-multipliers-entry-twin (FALSE): +½εΨ₁₂I₂.
p2-coupled-metrics-differ (TRUE, r = 2, not/nonzero): the coupled flows for κ and κ = 0 differ.
p2-coupled-metrics-differ-r1 (FALSE, r = 1, not/nonzero): they differ at r = 1 (they coincide).
p2-pr-e-rank-kernel (TRUE): rank n − 1 with the kernel certificate QEQ (Q = I − eeᵀ, E ∈ so(n)).
p2-pr-e-rank-kernel-twin (FALSE): rank n − 2 with the same certificate.
"""
from stiefelsym import Rank, admissible, claim, twisted
from stiefelsym.bases import matrix_of, so_basis
from stiefelsym.systems import stiefel_pairs_flow


def H_neum(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def trL3(s, sign):
    lam, A, V, F = s.lam, s.A, s.X @ s.X.T, s.Phi
    L = lam * F + V - lam * lam * A
    lam2, lam4 = lam * lam, lam * lam * lam * lam
    expansion = (s.tr(s.Ir) + lam2 * (3 * s.tr(F @ F @ V) - 3 * s.tr(A @ V))
                 + lam4 * (3 * s.tr(V @ A @ A) - sign * 3 * s.tr(F @ F @ A)) - lam4 * lam2 * s.tr(A @ A @ A))
    c4 = lambda t: t.tr(t.X.T @ t.A @ t.A @ t.X) - sign * t.tr(t.Phi @ t.Phi @ t.A)
    return {"tr L^3 expansion": s.tr(L @ L @ L) - expansion,
            "lambda^4 coefficient conserved": s.d(c4, s.dirac_flow(H_neum))}


@claim("p2-trL3-trIr", kind="pb", section="5", sizes=admissible(n_max=4))
def p_trL3(s):
    """tr 𝓛³ expansion with tr I_r."""
    return trL3(s, 1)


@claim("p2-trL3-trIr-twin", kind="pb", section="5", sizes=admissible(n_max=4))
def p_trL3_twin(s):
    """FALSE: +3trΦ²A."""
    return trL3(s, -1)


ON_V_N2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def mag_entry(s, c):
    m = twisted.multiplier_flow(s, H_E)
    return {"Pi": m["Pi"], "Lambda": m["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P + c * s.eps * s.Psi[0, 1] * s.Ir)}


@claim("p2-magnetic-multipliers-entry", kind="id", section="A1", sizes=ON_V_N2)
def p_mag(s):
    """Λ = XᵀAX − PᵀP − ½εΨ₁₂I₂."""
    return mag_entry(s, -s.q(1, 2))


@claim("p2-magnetic-multipliers-entry-twin", kind="id", section="A1", sizes=ON_V_N2)
def p_mag_twin(s):
    """FALSE: +½εΨ₁₂I₂."""
    return mag_entry(s, s.q(1, 2))


def H_coupled(kappa):
    def H(t, z):
        XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
        c = t.q(1, 2) + kappa(t)
        return (t.tr(z["P"].T @ z["P"]) / 2 - c * t.tr(XP @ XP) + t.tr(z["Q"].T @ z["Q"]) / 2 - c * t.tr(YQ @ YQ)
                + t.tr(z["X"].T @ t.A @ z["Y"]))
    return H


def coupled_metrics(s):
    z = {"X": s.X, "P": s.P, "Y": s.Y, "Q": s.Q}
    pairs = [("X", "P"), ("Y", "Q")]
    f = stiefel_pairs_flow(s, H_coupled(lambda t: t.kappa), z, pairs)
    g = stiefel_pairs_flow(s, H_coupled(lambda t: t.q(0)), z, pairs)
    return {"difference": [f[k] - g[k] for k in ("X", "P", "Y", "Q")]}


@claim("p2-coupled-metrics-differ", kind="not", expect="nonzero", section="A2",
       sizes=admissible(n_max=4, r_min=2, r_max=2, condition="r = 2"))
def p_differ(s):
    """At r = 2 the coupled flows for κ and κ = 0 differ."""
    return coupled_metrics(s)


@claim("p2-coupled-metrics-differ-r1", kind="not", expect="nonzero", section="A2",
       sizes=admissible(n_max=4, r_max=1, condition="r = 1"))
def p_differ_r1(s):
    """FALSE: at r = 1 the coupled flows for κ and κ = 0 differ."""
    return coupled_metrics(s)


def pr_e(xi, e):
    return xi @ e @ e.T + e @ e.T @ xi


def so_coords(M, m):
    return [M[i, j] for i in range(m) for j in range(i + 1, m)]


def pr_rank(s, k):
    e = s.X[:, 0:1]
    n = int(s.n)
    M = matrix_of(s, lambda xi: pr_e(xi, e), so_basis(s, "n"))
    Q = s.In - e @ e.T
    vecs = [so_coords(Q @ E @ Q, n) for E in so_basis(s, "n")]
    K = s.mat([list(row) for row in zip(*vecs)])
    return {"rank": Rank(M, k, kernel=K)}


@claim("p2-pr-e-rank-kernel", kind="dim", section="A1", sizes=admissible(n_max=4, n_min=2))
def p_pr(s):
    """rank n − 1 with kernel certificate."""
    return pr_rank(s, int(s.n) - 1)


@claim("p2-pr-e-rank-kernel-twin", kind="dim", section="A1", sizes=admissible(n_max=4, n_min=3))
def p_pr_twin(s):
    """FALSE: rank n − 2 with the same certificate."""
    return pr_rank(s, int(s.n) - 2)
