# ruff: noqa
"""Stop 71 (hidden): false twins of claims.py, one change each; each is expected to fail where numpy says it is
false (`fails_at`), and to hold at the degenerate sizes where numpy says it is true."""
from stiefelsym import Count, admissible, block, claim, comm
from stiefelsym.systems import coupled_point, derivative, double_point, stiefel_pairs_flow


def wedge(a, b):
    return a @ b.T - b @ a.T


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


@claim("n71-psi-equivariance-transposed", kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: r >= 3, erratum="twin: QΨQᵀ in place of QᵀΨQ")
def psi_equivariance_transposed(s):
    """Twin: Ψ(XQ, PQ) = QΨQᵀ (true for r ≤ 2: SO(2) is abelian)."""
    Q = (s.Ir - s.eta) @ (s.Ir + s.eta).inv()
    return {"Ψ(XQ,PQ) − QΨQᵀ": Psi_of(s.X @ Q, s.P @ Q) - Q @ s.Psi @ Q.T}


@claim("n71-dirac-bracket-sign", kind="pb", sizes=admissible(n_max=3, r_max=2),
       fails_at=lambda n, r: True, erratum="twin: − in front of the correction term")
def dirac_bracket_sign(s):
    """Twin: {f1, f2} = {f1, f2}_0 − Σ {F_i, f1}_0 C_ij {F_j, f2}_0."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    f1 = lambda t: t.tr(U.T @ t.X) + t.tr(V.T @ t.P)
    f2 = lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2
    r = int(s.r)
    F = []
    for i in range(r):
        for j in range(i, r):
            F.append(lambda t, i=i, j=j: (t.X.T @ t.X)[i, j] - (1 if i == j else 0))
            F.append(lambda t, i=i, j=j: (t.X.T @ t.P + t.P.T @ t.X)[i, j])
    m = len(F)
    C = s.mat([[s.canonical_bracket(F[i], F[j]) for j in range(m)] for i in range(m)], ("cond", "cond")).inv()
    b1 = [s.canonical_bracket(F[i], f1) for i in range(m)]
    b2 = [s.canonical_bracket(F[j], f2) for j in range(m)]
    d = s.canonical_bracket(f1, f2)
    for i in range(m):
        for j in range(m):
            d = d - b1[i] * C[i, j] * b2[j]
    return {"twin − engine's": d - s.bracket(f1, f2)}


@claim("n71-ne-lambda-sign", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: True,
       erratum="twin: −XΛ")
def ne_lambda_sign(s):
    """Twin: for κ = −½, Ṗ = −AX − XΛ."""
    X, P, A = s.X, s.P, s.A
    Lam = X.T @ A @ X - P.T @ P
    f = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2)
    return {"Ṗ − (−AX − XΛ)": f["P"] - (-(A @ X) - X @ Lam)}


@claim("n71-lema1-eta-v-sign", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r < n,
       erratum="twin: the blocks swapped")
def lema1_eta_v_sign(s):
    """Twin: [η, v] = vη(I − v) − (I − v)ηv (true at r = n, where I − v = 0)."""
    v = s.X @ s.X.T
    eta = s.generic("etaS", "n", "n", "sym")
    Qp = s.In - v
    return {"twin": comm(eta, v) - (v @ eta @ Qp - Qp @ eta @ v)}


@claim("n71-a-man-equals-l-man", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: True,
       erratum="twin: 𝓐*_man(λ) = 𝓛*_man(λ)")
def a_man_equals_l_man(s):
    """Twin: the printed 𝓐*_man(λ) is 𝓛*_man(λ) (it is 𝓛*_man(−λ))."""
    lam, X, P = s.lam, s.X, s.P
    R = s.resolvent(lam)
    Rp = (s.A + lam * s.In).inv()
    A_man = block([[X.T @ Rp @ P, X.T @ Rp @ X], [-(P.T @ Rp @ P), -(P.T @ Rp @ X)]])
    L_man = block([[-(X.T @ R @ P), -(X.T @ R @ X)], [P.T @ R @ P, P.T @ R @ X]])
    return {"twin": A_man - L_man}


@claim("n71-manakov-not-so-n-invariant", kind="pb", sizes=admissible(n_max=4), fails_at=lambda n, r: n >= 3,
       erratum="twin: Φ_ξ conserved by the Manakov flow")
def manakov_phi_conserved(s):
    """Twin: {⟨Φ, ξ⟩, H_A²} = 0 (true at n ≤ 2, where so(n) is abelian)."""
    xi = s.xi
    H2 = lambda t: -t.tr((t.A @ t.Phi + t.Phi @ t.A) @ t.Phi) / 4
    return {"{Φ_ξ, H_A²}": s.bracket(lambda t: -t.tr(t.Phi @ xi) / 2, H2)}


@claim("n71-ym-chain-sign", kind="id", sizes=admissible(n_max=5, r_max=1), fails_at=lambda n, r: True,
       erratum="twin: + sign")
def ym_chain_sign(s):
    """Twin: (Ae⊗e − e⊗eA)e + (ė∧e)ė = Ae + ((e, Ae) + (ė, ė))e."""
    e, ed, A = s.X, s.P, s.A
    lhs = (A @ e @ e.T - e @ e.T @ A) @ e + wedge(ed, e) @ ed
    return {"twin": lhs - (A @ e + e @ (e.T @ A @ e + ed.T @ ed))}


@claim("n71-coupled-euclid-diagonal-swapped", kind="lax", sizes=admissible(n_max=3), fails_at=lambda n, r: r >= 2,
       erratum="twin: D1 = −XᵀP, D2 = −YᵀQ")
def coupled_diag_swapped(s):
    """Twin: κ = −½ perturbed coupled system with D1 = −XᵀP, D2 = −YᵀQ (true at r = 1, where XᵀP = YᵀQ = 0)."""
    z = coupled_point(s)
    H = lambda t, w: (t.tr(w["P"].T @ w["P"]) / 2 + t.tr(w["Q"].T @ w["Q"]) / 2 + t.tr(w["X"].T @ t.A @ w["Y"])
                      + t.tr(w["X"].T @ w["P"] @ w["Y"].T @ w["Q"]))
    flow = stiefel_pairs_flow(s, H, z, [("X", "P"), ("Y", "Q")])

    def L(t, w):
        X, P, Y, Q, A, lam, I = w["X"], w["P"], w["Y"], w["Q"], t.A, t.lam, t.Ir
        F = lambda U, V: U.T @ t.resolvent(t.lam) @ t.resolvent(-t.lam) @ V
        return block([
            [lam * F(P, X), lam * F(P, P), F(A @ P, Y), -I + F(A @ P, Q)],
            [-lam * F(X, X), -lam * F(X, P), -F(A @ X, Y), -F(A @ X, Q)],
            [F(A @ Q, X), -I + F(A @ Q, P), lam * F(Q, Y), lam * F(Q, Q)],
            [-F(A @ Y, X), -F(A @ Y, P), -lam * F(Y, Y), -lam * F(Y, Q)]])
    X, P, Y, Q, A = z["X"], z["P"], z["Y"], z["Q"], s.A
    S = (X.T @ A @ Y + Y.T @ A @ X) / 2
    Lam, Pi = S - P.T @ P, S - Q.T @ Q
    O, I, lam = s.zeros(s.r, s.r, ("r", "r")), s.Ir, s.lam * s.Ir
    d1, d2 = -(X.T @ P), -(Y.T @ Q)
    Am = block([[d1, Lam, O, -lam], [I, d1, O, O], [O, -lam, d2, Pi], [O, O, I, d2]])
    return {"twin": derivative(s, L, z, flow) - comm(L(s, z), Am)}


@claim("n71-double-gl-no-transpose", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r >= 2,
       erratum="twin: X ↦ XR")
def double_gl_no_transpose(s):
    """Twin: X ↦ XR, Y ↦ YR⁻¹ keeps (D0) (true at r = 1)."""
    z = double_point(s)
    R = s.generic("Rgl", "r", "r")
    return {"twin": (z["X"] @ R).T @ (z["Y"] @ R.inv()) - s.Ir}


@claim("n71-ellipsoid-a-not-inverse", kind="id", sizes=admissible(n_max=4, r_max=1), fails_at=lambda n, r: True,
       erratum="twin: (y, Ay) = 1")
def ellipsoid_twin(s):
    """Twin: y = Cx lies on (y, Ay) = 1 (A = C²)."""
    C = s.generic("Csym", "n", "n", "sym")
    y = C @ s.X
    return {"twin": y.T @ C @ C @ y - s.Ir}


@claim("n71-normal-legendre-factor", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r >= 2,
       erratum="twin: P = Ẋ − XXᵀẊ")
def normal_legendre_factor(s):
    """Twin: with P = Ẋ − XXᵀẊ, Ψ(X, P) = XᵀẊ (true at r = 1, where XᵀẊ = 0)."""
    X, Xd = s.X, s.P
    P = Xd - X @ X.T @ Xd
    return {"twin": Psi_of(X, P) - X.T @ Xd}


@claim("n71-hb-jensen-factor", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r >= 2,
       erratum="twin: 𝔹 = κ·id")
def hb_jensen_factor(s):
    """Twin: H_𝔹 with 𝔹 = κ·id is H_κ (true at r = 1, where Ψ = XᵀP = 0)."""
    P, Psi = s.P, s.Psi
    H_B = s.tr(P.T @ P) / 2 - s.tr(Psi @ (s.kappa * Psi)) / 4
    H_k = s.tr(P.T @ P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(s.X.T @ P @ s.X.T @ P)
    return {"twin": H_B - H_k}


@claim("n71-jk-rank-r", kind="dim", sizes=admissible(n_max=4, r_min=2), fails_at=lambda n, r: True,
       erratum="twin: J_1..J_r independent")
def jk_rank_r(s):
    """Twin: J_1, …, J_r have r independent differentials (they have [r/2])."""
    from stiefelsym import Rank
    r = int(s.r)

    def pw(M, k):
        out = M
        for _ in range(k - 1):
            out = out @ M
        return out
    F_all = lambda t: [t.tr(pw(t.Psi, 2 * k)) for k in range(1, r + 1)]
    return {"twin": Rank(s.mat(s.jacobian(F_all)), r)}


@claim("n71-p-neutral-psi-factor", kind="id", sizes=admissible(n_max=4, where=lambda n, r: r < n),
       fails_at=lambda n, r: r >= 2, erratum="twin: Ψ = P_1")
def p_neutral_twin(s):
    """Twin: at X0, Ψ(X0, P0) = P_1 (it is 2P_1; true at r = 1, P_1 = 0)."""
    n, r = int(s.n), int(s.r)
    W = s.generic("W", "r", "r", "skew")
    Zg = s.generic("Zg", "n", "r")
    X0 = s.mat([[1 if i == j else 0 for j in range(r)] for i in range(n)], ("n", "r"))
    P0 = s.mat([[W[i, j] for j in range(r)] if i < r else [Zg[i, j] for j in range(r)] for i in range(n)], ("n", "r"))
    return {"twin": Psi_of(X0, P0) - W}


@claim("n71-counts-n-off-by-one", kind="dim", sizes=admissible(n_max=6), fails_at=lambda n, r: True,
       erratum="twin: N = (n−1)+…+(n−r) = r(n−r) + r(r+1)/2")
def counts_twin(s):
    n, r = int(s.n), int(s.r)
    return {"twin": Count(sum(n - l for l in range(1, r + 1)), r * (n - r) + r * (r + 1) // 2)}
