# ruff: noqa
"""False twins of claims.py, one change each; fails_at where the numpy check (indep.py) says false."""
from stiefelsym import Count, Rank, admissible, block, claim, comm, det
from stiefelsym.brackets import lambda1, lambda2

from _h71b_helpers import (I_nr, Phi_of, Psi_of, X0_of, Zrr, action_matrix, diag_blocks, dso, skew_nr, sym_nr,
                           r_lt_n)

E = "false twin (one change)"


@claim("n71b-lema1-h2-sign", paper=("LEMA1",), kind="id", sizes=admissible(n_max=5, **r_lt_n),
       fails_at=lambda n, r: True, erratum=E)
def h2_sign(s):
    """twin of h71b-lema1-h-blocks: h = [[h1, −h2], [h2ᵀ, 0]] (h2 sign)."""
    P1, P2 = s.generic("P1", "r", "r", "skew"), s.generic("P2", "n-r", "r")
    X0, P0 = X0_of(s), block([[P1], [P2]])
    h1, h2 = 2 * P1, -P2.T
    h = block([[h1, -h2], [h2.T, s.zeros(s.n - s.r, s.n - s.r, ("n-r", "n-r"))]])
    return {"Φ − h": Phi_of(X0, P0) - h}


@claim("n71b-iso-adjoint-transposed", paper=("iso",), kind="id", sizes=admissible(n_max=5, **r_lt_n),
       fails_at=lambda n, r: n - r >= 2, erratum=E)
def iso_transposed(s):
    """twin of h71b-iso-adjoint: B̂ᵀΦB̂ in place of B̂ΦB̂ᵀ (true at n − r = 1, where B = 1)."""
    P1, P2 = s.generic("P1", "r", "r", "skew"), s.generic("P2", "n-r", "r")
    X0 = X0_of(s)
    beta = skew_nr(s, "beta")
    I = I_nr(s)
    B = (I - beta) @ (I + beta).inv()
    Bh = diag_blocks(s, s.Ir, B)
    return {"Φ(X0, B̂P0) − B̂ᵀΦB̂": Phi_of(X0, block([[P1], [B @ P2]])) - Bh.T @ Phi_of(X0, block([[P1], [P2]])) @ Bh}


@claim("n71b-so-r-conjugation-order", paper=("P-neutral",), kind="id", sizes=admissible(n_max=5, **r_lt_n),
       fails_at=lambda n, r: r >= 3, erratum=E)
def so_r_order(s):
    """twin of h71b-so-r-at-x0: P1 ↦ QP1Q⁻¹ (true for r ≤ 2, SO(2) abelian)."""
    P1, P2 = s.generic("P1", "r", "r", "skew"), s.generic("P2", "n-r", "r")
    X0 = X0_of(s)
    Q = (s.Ir - s.eta) @ (s.Ir + s.eta).inv()
    R = diag_blocks(s, Q.T, I_nr(s))
    P0 = block([[P1], [P2]])
    return {"R P0 Q − (QP1Q⁻¹; P2Q)": R @ P0 @ Q - block([[Q @ P1 @ Q.inv()], [P2 @ Q]])}


@claim("n71b-so-r-h-kappa-factor", paper=("EM",), kind="id", sizes=admissible(n_max=5, **r_lt_n),
       fails_at=lambda n, r: r >= 2, erratum=E)
def so_r_factor(s):
    """twin: H_κ(X0, P0) = ½tr P2ᵀP2 − (½ + κ)tr P1² (P1 = 0 at r = 1)."""
    P1, P2 = s.generic("P1", "r", "r", "skew"), s.generic("P2", "n-r", "r")
    X0, P0 = X0_of(s), block([[P1], [P2]])
    Hk = s.tr(P0.T @ P0) / 2 - (s.q(1, 2) + s.kappa) * s.tr(X0.T @ P0 @ X0.T @ P0)
    return {"H": Hk - (s.tr(P2.T @ P2) / 2 - (s.q(1, 2) + s.kappa) * s.tr(P1 @ P1))}


@claim("n71b-ddim-isotropy-trivial", paper=("ddim",), kind="dim",
       sizes=admissible(n_max=6, where=lambda n, r: n - r >= 2, condition="n − r ≥ 2"),
       fails_at=lambda n, r: n - 2 * r >= 2, erratum=E)
def ddim_trivial(s):
    """twin of h71b-ddim-isotropy: SO(n−r)_{P0} trivial for every n (rank dim so(n − r)); false when
    dim so(n − 2r) > 0."""
    P2 = s.generic("P2", "n-r", "r")
    return {"rank": Rank(action_matrix(s, P2), dso(int(s.n) - int(s.r)))}


@claim("n71b-lema1-eta3-sign", paper=("LEMA1",), kind="id", sizes=admissible(n_max=5, **r_lt_n),
       fails_at=lambda n, r: (n, r) != (2, 1), erratum=E)
def eta3_sign(s):
    """twin of h71b-lema1-kernel-blocks: η3 = h2ξ2 − ξ1h2 (0 = 0 at (2,1): ξ1 = 0, ξ2 = 0)."""
    P1, P2 = s.generic("P1", "r", "r", "skew"), s.generic("P2", "n-r", "r")
    h1, h2 = 2 * P1, -P2.T
    xi1, xi2 = h1 @ h1 @ h1, skew_nr(s, "xi2")
    eta3 = h2 @ xi2 - xi1 @ h2
    Znn = s.zeros(s.n - s.r, s.n - s.r, ("n-r", "n-r"))
    xi = diag_blocks(s, xi1, xi2)
    H2 = block([[Zrr(s), h2], [-h2.T, Znn]])
    E3 = block([[Zrr(s), -eta3], [eta3.T, Znn]])
    return {"printed η3 equation": comm(xi, H2) + E3}


@claim("n71b-lambda-sign", paper=("LAMBDA",), kind="id", sizes=admissible(n_max=5),
       fails_at=lambda n, r: n >= 2, erratum=E)
def lambda_sign(s):
    """twin of (LAMBDA): +⟨h, [η, θ]⟩."""
    h, v = s.Phi, s.X @ s.X.T
    xi, zeta = s.xi, s.zeta
    eta, theta = s.generic("eta", "n", "n", "sym"), s.generic("theta", "n", "n", "sym")
    L = lambda1()(s, h + v, xi + eta, zeta + theta) - lambda2()(s, h + v, xi + eta, zeta + theta)
    return {"(LAMBDA)": L - (s.killing(h, comm(eta, theta)) + s.killing(s.A, comm(xi, theta) + comm(eta, zeta)))}


@claim("n71b-l4-denominator", paper=("L4",), kind="id", sizes=admissible(n_max=5),
       fails_at=lambda n, r: n >= 2, erratum=E)
def l4_denominator(s):
    """twin of h71b-l3-l4-coordinates: ξ_ij = [η, h]_ij / (a_i − a_j)."""
    n = int(s.n)
    h, a = s.Phi, s.a
    d = [s.scalar(f"d{i}") for i in range(n)]
    eta = s.mat([[d[i] if i == j else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    C = comm(eta, h)
    xi = s.mat([[C[i, j] / (a[i] - a[j]) if i != j else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    return {"(L4)": comm(xi, s.A) - comm(eta, h)}


@claim("n71b-submersion-gradient-sign", paper=("dot_XP2",), kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: n >= 2, erratum=E)
def submersion_sign(s):
    """twin: −∂H/∂X = −𝔸(Φ)P."""
    AA = s.sym_operator("AA")
    H = lambda t: -t.tr(AA(t.P @ t.X.T - t.X @ t.P.T) @ (t.P @ t.X.T - t.X @ t.P.T)) / 4
    HX, HP = s.gradient(H)
    return {"−∂H/∂X + 𝔸(Φ)P": -HX + AA(s.Phi) @ s.P}


@claim("n71b-neumann-gradient-factor", paper=("No",), kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: r >= 2, erratum=E)
def neumann_factor(s):
    """twin: (1 + κ) in place of (1 + 2κ) (true at r = 1, where XPᵀX = X(PᵀX) = 0 and PXᵀP = 0 on T*V)."""
    H = lambda t: (t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(t.X.T @ t.P @ t.X.T @ t.P)
                   + t.tr(t.X.T @ t.A @ t.X) / 2)
    HX, HP = s.gradient(H)
    X, P = s.X, s.P
    return {"−∂H/∂X": -HX - (-(s.A @ X) + (1 + s.kappa) * (P @ X.T @ P)),
            "∂H/∂P": HP - (P - (1 + s.kappa) * (X @ P.T @ X))}


@claim("n71b-neumann2-rank-so-r", paper=("NEUMANN2",), kind="dim", sizes=admissible(n_max=7),
       fails_at=lambda n, r: r >= 3, erratum=E)
def neumann2_rank(s):
    """twin: the generic-h1 count rank so(r) used at h1 = 0 (equal for r ≤ 2)."""
    n, r = int(s.n), int(s.r)
    sym = lambda m: m * (m + 1) // 2
    return {"dim": Count(r // 2 + dso(n - r) + sym(r) + sym(n - r), r * r + (n - r) ** 2)}


@claim("n71b-cp-body-is-space", paper=("mag*",), kind="id",
       sizes=admissible(n_max=5, r_is_n=True, condition="r = n"), fails_at=lambda n, r: n >= 2, erratum=E)
def cp_body(s):
    """twin: ω = 𝒳ᵀẊ equals −m = −𝒳ᵀM𝒳 (sign).  (The literal frame confusion ω = M, an r×r against an n×n
    matrix, is refused by the index spaces even at r = n.)"""
    flow = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 - t.tr(t.X.T @ t.P @ t.X.T @ t.P) / 2)
    return {"𝒳ᵀẊ + 𝒳ᵀM𝒳": s.X.T @ flow["X"] + s.X.T @ s.Phi @ s.X}


@claim("n71b-vv-minor-p", paper=("VV",), kind="id", sizes=admissible(n_max=5), fails_at=lambda n, r: True,
       erratum=E)
def vv_minor_p(s):
    """twin: the minor containing I_r is det P_I."""
    n, r = int(s.n), int(s.r)
    X, P = s.X, s.P
    I = list(range(r))
    rows = [[X[i, j] for j in range(r)] + [P[i, j] for j in range(r)] for i in I]
    rows += [[0] * r + [1 if a == b else 0 for b in range(r)] for a in range(r)]
    V = s.mat(rows, ("?", "?"))
    PI = s.mat([[P[i, j] for j in range(r)] for i in I], ("?", "?"))
    return {"minor − det P_I": det(s, V) - det(s, PI)}


@claim("n71b-a-metric-phi-conserved", paper=("A_XP",), kind="pb", realization="metric", sizes=admissible(n_max=4),
       fails_at=lambda n, r: n >= 2 and (n, r) != (2, 2), erratum=E)
def a_metric_phi(s):
    """twin: ds²_A is SO(n)-invariant, Φ conserved along (A_XP).  False: dΦ/dt = [PPᵀ, A⁻¹] ≠ 0, except at
    (2,2), where P = AXW, W = wJ, PPᵀ = w²A² commutes with A⁻¹ (found by the numpy check)."""
    flow = s.dirac_flow(lambda t: t.tr(t.P.T @ t.Ainv @ t.P) / 2)
    return {"dΦ/dt": s.d(lambda t: t.P @ t.X.T - t.X @ t.P.T, flow)}


@claim("n71b-psi-is-xtp", paper=("grassmannian",), kind="id", sizes=admissible(n_max=5),
       fails_at=lambda n, r: r >= 2, erratum=E)
def psi_is_xtp(s):
    """twin: Ψ = XᵀP (both 0 at r = 1)."""
    return {"Ψ − XᵀP": s.Psi - s.X.T @ s.P}
