"""h2 hidden statements from §8 (The dual Lax pair and geometric interpretation of integrals).
Truth: by hand (below) and numerically by ../truth_numpy.py (logs/truth_numpy*.log).
R = (λI − A)⁻¹; 𝓛* = [[−XᵀRP, −XᵀRX], [I + PᵀRP, PᵀRX]] (LA3); Λ = XᵀAX − PᵀP.

T17 h2-resolvent-identity (TRUE): AR = RA = λR − I (the identity quoted after Theorem DUAL).
    -twin (FALSE): AR = λR + I.
T18 h2-dual-right-conjugation (TRUE): under the right action (XQ, PQ), 𝓛* ↦ diag(Q,Q)ᵀ𝓛* diag(Q,Q); infinitesimally
    d𝓛* along (Xη, Pη) = [𝓛*, diag(η, η)] ("𝓛* is not SO(r)-invariant but its spectral curve is").
    -twin (FALSE, r >= 2): = [diag(η, η), 𝓛*].
T19 h2-dual-e2-resolvent (TRUE): e_2(𝓛*) = −½tr 𝓛*² = tr(RXXᵀ) − ½tr(RΦRΦ), i.e. 𝓘_2 = a(λ)(Σ (XXᵀ)_ii/(λ−a_i)
    + Σ_{i<j} Φ_ij²/((λ−a_i)(λ−a_j))) written without coordinates (2r-integrals, explicit 𝓘_2); also tr 𝓛* = 0.
    -twin (FALSE, n >= 2): + ½tr(RΦRΦ).
T20 h2-dual-lax-printed-flows (TRUE): Theorem DUAL with the printed flows as tangent vectors (not Dirac flows):
    along (N0_XP2) Ẋ = P − XPᵀX, Ṗ = −AX + PXᵀP − XPᵀP + XXᵀAX: d𝓛*/dt = [𝓛*, 𝓐*_N]; along (NE_XP) Ẋ = P,
    Ṗ = −AX − XPᵀP + XXᵀAX: d𝓛*/dt = [𝓛*, 𝓐*_E].
    -twin (FALSE, r >= 2): along (N0_XP2) with 𝓐*_E (differs by diag(XᵀP, XᵀP), which does not commute with 𝓛*).
    -twin2 (FALSE): along (NE_XP), 𝓛* without the I_r block (i.e. 𝓛*_man) with 𝓐*_E.
T21 h2-moser-uhlenbeck (TRUE, r = 1, Mum_geod): F_i = e_i² + Σ_{j≠i}(e_ip_j − e_jp_i)²/(a_i − a_j):
    ΣF_i = 1, Σa_iF_i = (Ae,e) + (p,p) = 2H_neum, ΣF_i/a_i = (A⁻¹e,e)(1 − (A⁻¹p,p)) + (A⁻¹e,p)².
    -twin (FALSE, r = 1, n >= 2): Σa_iF_i = (Ae,e) + 2(p,p).  -twin2 (FALSE, r = 1, n >= 2): (1 + (A⁻¹p,p)).
"""
from stiefelsym import admissible, block, claim, comm

N = 4


def L_dual(t):
    R = t.resolvent(t.lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def L_man(t):
    R = t.resolvent(t.lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [P.T @ R @ P, P.T @ R @ X]])


def Lam(s):
    return s.X.T @ s.A @ s.X - s.P.T @ s.P


def A_N(s):
    return block([[s.X.T @ s.P, s.Ir], [Lam(s) - s.lam * s.Ir, -(s.P.T @ s.X)]])


def A_E(s):
    z = s.zeros(s.r, s.r, ("r", "r"))
    return block([[z, s.Ir], [Lam(s) - s.lam * s.Ir, z]])


def flow_N(s):
    X, P, A = s.X, s.P, s.A
    return {"X": P - X @ P.T @ X, "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}


def flow_E(s):
    X, P, A = s.X, s.P, s.A
    return {"X": P, "P": -(A @ X) - X @ P.T @ P + X @ X.T @ A @ X}


# ---------------------------------------------------------------- T17
@claim("h2-resolvent-identity", kind="id", section="8", sizes=admissible(n_max=5))
def resolvent_identity(s):
    """TRUE: AR = RA = λR − I."""
    R = s.resolvent(s.lam)
    return {"AR - (lam R - I)": s.A @ R - (s.lam * R - s.In), "RA - AR": R @ s.A - s.A @ R}


@claim("h2-resolvent-identity-twin", kind="id", section="8", sizes=admissible(n_max=5))
def resolvent_identity_twin(s):
    """FALSE: AR = λR + I."""
    R = s.resolvent(s.lam)
    return {"AR - (lam R + I)": s.A @ R - (s.lam * R + s.In)}


# ---------------------------------------------------------------- T18
def K_eta(s):
    z = s.zeros(s.r, s.r, ("r", "r"))
    return block([[s.eta, z], [z, s.eta]])


@claim("h2-dual-right-conjugation", kind="id", section="8", sizes=admissible(n_max=N))
def dual_right_conjugation(s):
    """TRUE: d𝓛* along (Xη, Pη) = [𝓛*, diag(η, η)]."""
    return {"dL* - [L*, K]": s.d(L_dual, {"X": s.X @ s.eta, "P": s.P @ s.eta}) - comm(L_dual(s), K_eta(s))}


@claim("h2-dual-right-conjugation-twin", kind="id", section="8", sizes=admissible(n_max=N, r_min=2, condition="r >= 2"))
def dual_right_conjugation_twin(s):
    """FALSE (r >= 2): d𝓛* along (Xη, Pη) = [diag(η, η), 𝓛*]."""
    return {"dL* - [K, L*]": s.d(L_dual, {"X": s.X @ s.eta, "P": s.P @ s.eta}) - comm(K_eta(s), L_dual(s))}


# ---------------------------------------------------------------- T19
@claim("h2-dual-e2-resolvent", kind="id", section="8", sizes=admissible(n_max=5))
def dual_e2(s):
    """TRUE: −½tr 𝓛*² = tr(RXXᵀ) − ½tr(RΦRΦ), tr 𝓛* = 0."""
    L, R = L_dual(s), s.resolvent(s.lam)
    return {"e2": -s.tr(L @ L) / 2 - (s.tr(R @ s.X @ s.X.T) - s.tr(R @ s.Phi @ R @ s.Phi) / 2),
            "tr L*": s.tr(L)}


@claim("h2-dual-e2-resolvent-twin", kind="id", section="8", sizes=admissible(n_max=5, n_min=2, condition="n >= 2"))
def dual_e2_twin(s):
    """FALSE (n >= 2): −½tr 𝓛*² = tr(RXXᵀ) + ½tr(RΦRΦ)."""
    L, R = L_dual(s), s.resolvent(s.lam)
    return {"e2": -s.tr(L @ L) / 2 - (s.tr(R @ s.X @ s.X.T) + s.tr(R @ s.Phi @ R @ s.Phi) / 2)}


# ---------------------------------------------------------------- T20
@claim("h2-dual-lax-printed-flows", kind="lax", section="8", sizes=admissible(n_max=N))
def dual_lax_printed(s):
    """TRUE: (LA3) with (LA4) along the printed (N0_XP2) and (NE_XP)."""
    L = L_dual(s)
    return {"normal": s.d(L_dual, flow_N(s)) - comm(L, A_N(s)),
            "euclidean": s.d(L_dual, flow_E(s)) - comm(L, A_E(s))}


@claim("h2-dual-lax-printed-flows-twin", kind="lax", section="8", sizes=admissible(n_max=N, r_min=2, condition="r >= 2"))
def dual_lax_printed_twin(s):
    """FALSE (r >= 2): along (N0_XP2) with the Euclidean 𝓐*."""
    return {"normal with A_E": s.d(L_dual, flow_N(s)) - comm(L_dual(s), A_E(s))}


@claim("h2-dual-lax-printed-flows-twin2", kind="lax", section="8", sizes=admissible(n_max=N))
def dual_lax_printed_twin2(s):
    """FALSE: along (NE_XP), 𝓛*_man (no I_r block) with 𝓐*_E."""
    return {"euclidean, L*_man": s.d(L_man, flow_E(s)) - comm(L_man(s), A_E(s))}


# ---------------------------------------------------------------- T21
def _moser(s):
    n = s.n
    a = s.a
    e = [s.X[i, 0] for i in range(n)]
    p = [s.P[i, 0] for i in range(n)]
    F = []
    for i in range(n):
        acc = e[i] * e[i]
        for j in range(n):
            if j != i:
                w = e[i] * p[j] - e[j] * p[i]
                acc = acc + w * w / (a[i] - a[j])
        F.append(acc)
    return a, F


def _sum(s, xs):
    acc = s.q(0)
    for x in xs:
        acc = acc + x
    return acc


R1 = admissible(n_max=5, r_max=1, condition="r = 1")
R1n2 = admissible(n_max=5, r_max=1, n_min=2, condition="r = 1, n >= 2")


@claim("h2-moser-uhlenbeck", kind="id", section="8", sizes=R1)
def moser(s):
    """TRUE (r = 1): ΣF_i = 1, Σa_iF_i = (Ae,e) + (p,p), ΣF_i/a_i = (A⁻¹e,e)(1 − (A⁻¹p,p)) + (A⁻¹e,p)²."""
    a, F = _moser(s)
    e, p, Ai = s.X, s.P, s.Ainv
    eAe, pp = s.tr(e.T @ s.A @ e), s.tr(p.T @ p)
    eAie, pAip, eAip = s.tr(e.T @ Ai @ e), s.tr(p.T @ Ai @ p), s.tr(e.T @ Ai @ p)
    return {"sum F - 1": _sum(s, F) - s.q(1),
            "sum a F": _sum(s, [a[i] * F[i] for i in range(s.n)]) - (eAe + pp),
            "sum F/a": _sum(s, [F[i] / a[i] for i in range(s.n)]) - (eAie * (s.q(1) - pAip) + eAip * eAip)}


@claim("h2-moser-uhlenbeck-twin", kind="id", section="8", sizes=R1n2)
def moser_twin(s):
    """FALSE: Σa_iF_i = (Ae,e) + 2(p,p)."""
    a, F = _moser(s)
    return {"sum a F": _sum(s, [a[i] * F[i] for i in range(s.n)]) - (s.tr(s.X.T @ s.A @ s.X) + 2 * s.tr(s.P.T @ s.P))}


@claim("h2-moser-uhlenbeck-twin2", kind="id", section="8", sizes=R1n2)
def moser_twin2(s):
    """FALSE: ΣF_i/a_i = (A⁻¹e,e)(1 + (A⁻¹p,p)) + (A⁻¹e,p)²."""
    a, F = _moser(s)
    e, p, Ai = s.X, s.P, s.Ainv
    eAie, pAip, eAip = s.tr(e.T @ Ai @ e), s.tr(p.T @ Ai @ p), s.tr(e.T @ Ai @ p)
    return {"sum F/a": _sum(s, [F[i] / a[i] for i in range(s.n)]) - (eAie * (s.q(1) + pAip) + eAip * eAip)}
