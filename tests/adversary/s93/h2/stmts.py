# ruff: noqa
"""Statements of stop 93 h2: true ones (t_) and false twins (f_), each mirrored in truth.py."""
from stiefelsym import Count, Rank, admissible, block, claim, comm, det

SZ = admissible(n_max=3)


def H_kin(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("t-xtx", kind="id", sizes=SZ)
def t_xtx(s):
    """XᵀX = I_r."""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("f-xxt", kind="id", sizes=SZ)
def f_xxt(s):
    """XXᵀ = I_n."""
    return {"r": s.X @ s.X.T - s.In}


@claim("t-tangent", kind="id", sizes=SZ)
def t_tangent(s):
    """XᵀP + PᵀX = 0."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("f-tangent", kind="id", sizes=SZ)
def f_tangent(s):
    """XᵀP − PᵀX = 0."""
    return {"r": s.X.T @ s.P - s.P.T @ s.X}


@claim("t-phix", kind="id", sizes=SZ)
def t_phix(s):
    """ΦX = P − XPᵀX."""
    return {"r": s.Phi @ s.X - s.P + s.X @ s.P.T @ s.X}


@claim("f-phix", kind="id", sizes=SZ)
def f_phix(s):
    """ΦX = P + XPᵀX."""
    return {"r": s.Phi @ s.X - s.P - s.X @ s.P.T @ s.X}


@claim("t-entries", kind="id", sizes=SZ)
def t_entries(s):
    """Σ X_ij² = r, read entry by entry."""
    n, r = int(s.n), int(s.r)
    tot = s.q(0)
    for i in range(n):
        for j in range(r):
            tot = tot + s.X[i, j] * s.X[i, j]
    return {"r": tot - s.tr(s.Ir)}


@claim("f-entries", kind="id", sizes=SZ)
def f_entries(s):
    """Σ_{i<n} X_i1² = 1 (the last row left out)."""
    n = int(s.n)
    tot = s.q(0)
    for i in range(n - 1):
        tot = tot + s.X[i, 0] * s.X[i, 0]
    return {"r": tot - 1}


@claim("t-mat-rebuild", kind="id", sizes=SZ)
def t_mat_rebuild(s):
    """X rebuilt from its entries is X."""
    n, r = int(s.n), int(s.r)
    M = s.mat([[s.X[i, j] for j in range(r)] for i in range(n)], ("n", "r"))
    return {"r": M - s.X}


@claim("f-mat-swap", kind="id", sizes=admissible(n_max=3, n_min=2))
def f_mat_swap(s):
    """X with its first two rows swapped is X."""
    n, r = int(s.n), int(s.r)
    rows = [[s.X[i, j] for j in range(r)] for i in range(n)]
    rows[0], rows[1] = rows[1], rows[0]
    return {"r": s.mat(rows, ("n", "r")) - s.X}


@claim("t-untyped", kind="id", sizes=SZ)
def t_untyped(s):
    """XᵀX rebuilt untyped is I_r."""
    r = int(s.r)
    G = s.X.T @ s.X
    M = s.mat([[G[i, j] for j in range(r)] for i in range(r)], ("?", "?"))
    return {"r": M - s.Ir}


@claim("f-untyped", kind="id", sizes=SZ)
def f_untyped(s):
    """XXᵀ rebuilt untyped is I_n."""
    n = int(s.n)
    G = s.X @ s.X.T
    M = s.mat([[G[i, j] for j in range(n)] for i in range(n)], ("?", "?"))
    return {"r": M - s.In}


@claim("t-block", kind="id", sizes=SZ)
def t_block(s):
    """[X P]ᵀ[X P] = [[I, XᵀP], [PᵀX, PᵀP]]."""
    M = block([[s.X, s.P]])
    return {"r": M.T @ M - block([[s.Ir, s.X.T @ s.P], [s.P.T @ s.X, s.P.T @ s.P]])}


@claim("f-block", kind="id", sizes=SZ)
def f_block(s):
    """[X P]ᵀ[X P] = [[I, XᵀP], [XᵀP, PᵀP]]."""
    M = block([[s.X, s.P]])
    return {"r": M.T @ M - block([[s.Ir, s.X.T @ s.P], [s.X.T @ s.P, s.P.T @ s.P]])}


@claim("t-resolvent", kind="id", sizes=SZ)
def t_resolvent(s):
    """R(λ) − R(μ) = (μ − λ)R(λ)R(μ)."""
    mu = s.scalar("mu")
    return {"r": s.resolvent(s.lam) - s.resolvent(mu) - (mu - s.lam) * (s.resolvent(s.lam) @ s.resolvent(mu))}


@claim("f-resolvent", kind="id", sizes=SZ)
def f_resolvent(s):
    """R(λ) − R(μ) = (λ − μ)R(λ)R(μ)."""
    mu = s.scalar("mu")
    return {"r": s.resolvent(s.lam) - s.resolvent(mu) - (s.lam - mu) * (s.resolvent(s.lam) @ s.resolvent(mu))}


@claim("t-lamtrace", kind="id", sizes=SZ)
def t_lamtrace(s):
    """tr(R(λ)A) = λ tr R(λ) − n."""
    R = s.resolvent(s.lam)
    return {"r": s.tr(R @ s.A) - s.lam * s.tr(R) + s.tr(s.In)}


@claim("f-lamtrace", kind="id", sizes=SZ)
def f_lamtrace(s):
    """tr(R(λ)A) = λ tr R(λ) − r."""
    R = s.resolvent(s.lam)
    return {"r": s.tr(R @ s.A) - s.lam * s.tr(R) + s.tr(s.Ir)}


@claim("t-second", kind="id", sizes=SZ)
def t_second(s):
    """YᵀY = I_r and YᵀQ + QᵀY = 0."""
    return {"a": s.Y.T @ s.Y - s.Ir, "b": s.Y.T @ s.Q + s.Q.T @ s.Y}


@claim("f-second", kind="id", sizes=SZ)
def f_second(s):
    """XᵀY = I_r."""
    return {"a": s.X.T @ s.Y - s.Ir}


@claim("f-second-q", kind="id", sizes=SZ)
def f_second_q(s):
    """XᵀQ + QᵀX = 0."""
    return {"a": s.X.T @ s.Q + s.Q.T @ s.X}


@claim("t-complex", kind="id", sizes=SZ)
def t_complex(s):
    """Z*Z = I and Z*V + V*Z = 0, realified."""
    Z, V = s.Zc, s.Zc_dot
    return {"a": Z.T @ Z - s.identity(2 * s.r, "r+r"), "b": Z.T @ V + V.T @ Z}


@claim("f-complex", kind="id", sizes=SZ)
def f_complex(s):
    """ZZ* = I_n, realified."""
    Z = s.Zc
    return {"a": Z @ Z.T - s.identity(2 * s.n, "n+n")}


@claim("f-complex-v", kind="id", sizes=SZ)
def f_complex_v(s):
    """Z*V − V*Z = 0, realified."""
    Z, V = s.Zc, s.Zc_dot
    return {"b": Z.T @ V - V.T @ Z}


def Phi_xi(t):
    return t.killing(t.Phi, t.xi)


def Phi_zeta(t):
    return t.killing(t.Phi, t.zeta)


def Psi_eta(t):
    return t.killing(t.Psi, t.eta)


@claim("t-bracket", kind="pb", sizes=SZ)
def t_bracket(s):
    """{Φ_ξ, Φ_ζ} = ⟨Φ, [ξ, ζ]⟩ and {Φ_ξ, Ψ_η} = 0."""
    return {"a": s.bracket(Phi_xi, Phi_zeta) - s.killing(s.Phi, comm(s.xi, s.zeta)),
            "b": s.bracket(Phi_xi, Psi_eta)}


@claim("f-bracket", kind="pb", sizes=SZ)
def f_bracket(s):
    """{Φ_ξ, Φ_ζ} = −⟨Φ, [ξ, ζ]⟩."""
    return {"a": s.bracket(Phi_xi, Phi_zeta) + s.killing(s.Phi, comm(s.xi, s.zeta))}


@claim("f-bracket0", kind="pb", sizes=SZ)
def f_bracket0(s):
    """{Φ_ξ, Φ_ζ} = 0."""
    return {"a": s.bracket(Phi_xi, Phi_zeta)}


@claim("t-gradient", kind="id", sizes=SZ)
def t_gradient(s):
    """The ambient gradient of ½tr PᵀP + ½tr XᵀAX is (AX, P)."""
    HX, HP = s.gradient(H_kin)
    return {"X": HX - s.A @ s.X, "P": HP - s.P}


@claim("f-gradient", kind="id", sizes=SZ)
def f_gradient(s):
    """The ambient gradient of ½tr PᵀP + ½tr XᵀAX is (2AX, P)."""
    HX, HP = s.gradient(H_kin)
    return {"X": HX - 2 * (s.A @ s.X), "P": HP - s.P}


@claim("t-flow-phi", kind="id", sizes=SZ)
def t_flow_phi(s):
    """Along the Neumann flow dΦ/dt = [XXᵀ, A] and dΨ/dt = 0."""
    flow = s.dirac_flow(H_kin)
    return {"phi": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A), "psi": s.d(lambda t: t.Psi, flow)}


@claim("f-flow-phi", kind="id", sizes=SZ)
def f_flow_phi(s):
    """Along the Neumann flow dΦ/dt = [A, XXᵀ]."""
    flow = s.dirac_flow(H_kin)
    return {"phi": s.d(lambda t: t.Phi, flow) - comm(s.A, s.X @ s.X.T)}


@claim("f-flow-h", kind="id", sizes=SZ)
def f_flow_h(s):
    """Along the Neumann flow d/dt tr(XᵀAX) = 0."""
    flow = s.dirac_flow(H_kin)
    return {"h": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), flow)}


@claim("t-flow-h", kind="id", sizes=SZ)
def t_flow_h(s):
    """Along the Neumann flow the Hamiltonian is conserved."""
    flow = s.dirac_flow(H_kin)
    return {"h": s.d(H_kin, flow)}


@claim("t-killing", kind="id", sizes=SZ)
def t_killing(s):
    """⟨Φ, Φ⟩ = tr PᵀP + ½⟨Ψ, Ψ⟩."""
    return {"r": s.killing(s.Phi, s.Phi) - s.tr(s.P.T @ s.P) - s.killing(s.Psi, s.Psi) / 2}


@claim("f-killing", kind="id", sizes=SZ)
def f_killing(s):
    """⟨Φ, Φ⟩ = tr PᵀP − ½⟨Ψ, Ψ⟩."""
    return {"r": s.killing(s.Phi, s.Phi) - s.tr(s.P.T @ s.P) + s.killing(s.Psi, s.Psi) / 2}


@claim("t-tangent-d", kind="id", sizes=SZ)
def t_tangent_d(s):
    """d tr(XᵀX) along ξX vanishes."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.X), {"X": s.xi @ s.X})}


@claim("f-tangent-d", kind="id", sizes=SZ)
def f_tangent_d(s):
    """d tr(XᵀAX) along ξX vanishes."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), {"X": s.xi @ s.X})}


@claim("t-det", kind="id", sizes=SZ)
def t_det(s):
    """det XᵀX = 1."""
    return {"r": det(s, s.X.T @ s.X) - 1}


@claim("f-det", kind="id", sizes=SZ)
def f_det(s):
    """det(XᵀX + PᵀP) = 1."""
    return {"r": det(s, s.X.T @ s.X + s.P.T @ s.P) - 1}


def phi_rank(n, r):
    m = min(2 * r, n)
    return 2 * (m // 2)


@claim("t-rank-phi", kind="dim", sizes=SZ)
def t_rank_phi(s):
    """rank Φ = 2⌊min(2r, n)/2⌋."""
    return {"rank": Rank(s.Phi, phi_rank(int(s.n), int(s.r)))}


@claim("f-rank-phi", kind="dim", sizes=SZ)
def f_rank_phi(s):
    """rank Φ = min(2r, n)."""
    return {"rank": Rank(s.Phi, min(2 * int(s.r), int(s.n)))}


def cons(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


@claim("t-rank-jac", kind="dim", sizes=SZ)
def t_rank_jac(s):
    """The constraints are independent: rank of their Jacobian is r(r + 1)."""
    r = int(s.r)
    return {"rank": Rank(s.mat(s.jacobian(cons, symmetric=True)), r * (r + 1))}


@claim("f-rank-jac", kind="dim", sizes=SZ)
def f_rank_jac(s):
    """rank of the constraints' Jacobian is r(r + 1) − 1."""
    r = int(s.r)
    return {"rank": Rank(s.mat(s.jacobian(cons, symmetric=True)), r * (r + 1) - 1)}


@claim("t-count", kind="dim", sizes=SZ)
def t_count(s):
    """dim T*V = 2nr − r(r + 1)."""
    n, r = int(s.n), int(s.r)
    return {"c": Count(2 * n * r - r * (r + 1), 2 * n * r - 2 * (r * (r + 1) // 2))}


@claim("f-count", kind="dim", sizes=SZ)
def f_count(s):
    """dim T*V = 2nr − r(r − 1)."""
    n, r = int(s.n), int(s.r)
    return {"c": Count(2 * n * r - r * (r - 1), 2 * n * r - r * (r + 1))}


@claim("t-xi", kind="id", sizes=SZ)
def t_xi(s):
    """ξ + ξᵀ = 0 and tr(ξ A ξ) = tr(A ξ²)."""
    return {"a": s.xi + s.xi.T, "b": s.tr(s.xi @ s.A @ s.xi) - s.tr(s.A @ s.xi @ s.xi)}


@claim("f-xi", kind="id", sizes=SZ)
def f_xi(s):
    """tr(ξAξᵀ) = tr(Aξ²)."""
    return {"b": s.tr(s.xi @ s.A @ s.xi.T) - s.tr(s.A @ s.xi @ s.xi)}


@claim("t-nonzero", kind="not", expect="nonzero", sizes=SZ)
def t_nonzero(s):
    """XXᵀ − I_n does not vanish (r < n)."""
    return {"r": s.X @ s.X.T - s.In}


@claim("t-nonzero-psi", kind="not", expect="nonzero", sizes=admissible(n_max=3, r_min=2))
def t_nonzero_psi(s):
    """Ψ does not vanish (r >= 2)."""
    return {"r": s.Psi}


@claim("f-nonzero", kind="not", expect="nonzero", sizes=SZ)
def f_nonzero(s):
    """XᵀX − I_r does not vanish."""
    return {"r": s.X.T @ s.X - s.Ir}
