"""s88h2: hidden statements of §8 (dual Lax pair, spectral curve, Chasles cones), each TRUE with a FALSE twin.

Notation: R = (λI − A)⁻¹, U = (X, P) (n × 2r), N = [[0, 0], [I_r, 0]], J = [[0, I], [−I, 0]], K = XᵀP (skew on
T*V), Φ = PXᵀ − XPᵀ, 𝒱 = [[X, P], [0, I_r]] ((n+r) × 2r), B(λ) = diag(R, I_r), M = 𝒱ᵀB𝒱.
Truth by hand (below) and by truth_numpy.py (no stiefelsym import).

 s88h2-factor (TRUE): 𝓛*(λ) = N + [−Xᵀ; Pᵀ] R [P, X]  (read off (LA3)).
 s88h2-factor-twin (FALSE): 𝓛*(λ) = N + [Xᵀ; Pᵀ] R [P, X]  (sign of the first block row; every r).
 s88h2-lambda-expansion (TRUE): λ(𝓛* − N) = [[−XᵀP, −I], [PᵀP, PᵀX]] + [−Xᵀ; Pᵀ] A R [P, X]
   (λR = I + AR, XᵀX = I).
 s88h2-lambda-expansion-twin (FALSE): upper-left block +XᵀP (K ≠ 0 needs r ≥ 2; r = 1: K = 0, the twin is TRUE).
 s88h2-trace-square (TRUE): tr 𝓛*(λ)² = tr(ΦRΦR) − 2 tr(XᵀRX)  (𝓛* = N + C, tr C² = tr(ΦRΦR), tr NC = tr C₁₂).
 s88h2-trace-square-twin (FALSE): tr 𝓛*(λ)² = tr(ΦRΦR) + 2 tr(XᵀRX).
 s88h2-det-r1 (TRUE, r = 1): det 𝓛*(λ) = −½ tr 𝓛*(λ)² = (xᵀRx)(1 + pᵀRp) − (xᵀRp)² (2×2 traceless; the
   discriminant of the quadratic form of the 2-plane Σ̄ on the cone Q̄(λ), Gen_Chasles at r = 1).
 s88h2-det-r1-twin (FALSE, r = 1, n >= 2; at n = 1 p = 0 and it holds): det 𝓛*(λ) = (xᵀRx)(1 + pᵀRp) + (xᵀRp)².
 s88h2-tangent-vector-r1 (TRUE, r = 1): w = 𝒱 adj(M) E₁ satisfies 𝒱ᵀBw = det(M) E₁ and ⟨w, Bw⟩ = det(M) adj(M)₁₁
   (so on det M = 0 the plane touches the cone along w, Prop. tangency).
 s88h2-tangent-vector-r1-twin (FALSE): 𝒱ᵀBw = det(M) E₂.
 s88h2-tangent-vector-r2 (TRUE, r = 2, adjugate from cofactors), -twin (FALSE): the same at r = 2.
 s88h2-cauchy-binet (TRUE, 2r ≤ n): e_{2r}(Φ) = Σ_I |Φ|^I_I = Σ_I det(U_I)² = det(UᵀU) = det(PᵀP + K²).
 s88h2-cauchy-binet-twin (FALSE, r ≥ 2): e_{2r}(Φ) = det(PᵀP − K²).
 s88h2-symplectic (TRUE): 𝓛*ᵀJ + J𝓛* = 0.
 s88h2-symplectic-twin (FALSE): 𝓛*ᵀJ − J𝓛* = 0.
 s88h2-trace-conserved (TRUE): tr(ΦRΦR) − 2tr(XᵀRX) is conserved along (NE_XP) and (N0_XP2) (it is tr 𝓛*²).
 s88h2-trace-conserved-twin (FALSE, r < n): tr(ΦRΦR) + 2tr(XᵀRX) conserved along (NE_XP)
   (the difference is 4 d/dt tr XᵀRX = 8 tr(XᵀRP), which vanishes at r = n: P = XK, tr(R·XKXᵀ) = 0).
 s88h2-resolvent (TRUE): 𝓛*(λ) − 𝓛*(μ) = (μ − λ)[−Xᵀ; Pᵀ] R(λ)R(μ) [P, X].
 s88h2-resolvent-twin (FALSE): (λ − μ) instead.
 s88h2-rank-C (TRUE): rank(𝓛*(λ) − N) = min(n, 2r) generically.
 s88h2-rank-C-twin (FALSE where n < 2r): rank 2r (sizes with n < 2r only).
 s88h2-rank-V (TRUE): rank 𝒱 = 2r at every point.
 s88h2-rank-V-twin (FALSE): rank 𝒱 = 2r − 1 generically.
 s88h2-rotation (TRUE): B ∈ SO(r) (Cayley of η): 𝒱(XB, PB) diag(Bᵀ, Bᵀ) = diag(I_n, Bᵀ) 𝒱(X, P), and
   det M(XB, PB) = det M(X, P) (fixed sizes).
 s88h2-rotation-twin (FALSE, r ≥ 2): … = diag(I_n, B) 𝒱(X, P).
 s88h2-uhlenbeck-sums (TRUE, r = 1): Σ F_i = 1 and Σ a_i F_i = xᵀAx + pᵀp.
 s88h2-uhlenbeck-sums-twin (FALSE, r = 1, n >= 2): Σ a_i F_i = xᵀAx + ½pᵀp.
"""
from __future__ import annotations

from stiefelsym import Rank, admissible, block, claim, det, elementary

ANY = admissible(n_max=4)
R1 = admissible(n_max=4, r_max=1, condition="r = 1")
R1N2 = admissible(n_max=4, n_min=2, r_max=1, condition="r = 1, n >= 2")
RLTN = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")
R2UP = admissible(n_max=4, r_min=2, condition="r >= 2")
TWO_R_LE_N = admissible(n_max=5, where=lambda n, r: 2 * r <= n, condition="2r <= n")
TWO_R_LE_N_R2 = admissible(n_max=5, r_min=2, where=lambda n, r: 2 * r <= n, condition="2r <= n, r >= 2")
N_LT_2R = admissible(n_max=4, where=lambda n, r: n < 2 * r, condition="n < 2r")


def Ldual(s, X, P, mu):
    R = s.resolvent(mu)
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, P.T @ R @ X]])


def Nmat(s):
    z = s.zeros(s.r, s.r, ("r", "r"))
    return block([[z, z], [s.Ir, z]])


def Jmat(s):
    z = s.zeros(s.r, s.r, ("r", "r"))
    return block([[z, s.Ir], [-s.Ir, z]])


def left(s, sign=-1):
    return block([[sign * s.X.T], [s.P.T]])


def right(s):
    return block([[s.P, s.X]])


def Vmat(s, X, P):
    z = s.zeros(s.r, s.r, ("r", "r"))
    return block([[X, P], [s.zeros(s.r, s.r, ("r", "r")), s.Ir]]) if False else block([[X, P], [z, s.Ir]])


def Bmat(s, mu):
    R = s.resolvent(mu)
    zn = s.zeros(s.n, s.r, ("n", "r"))
    return block([[R, zn], [zn.T, s.Ir]])


def H_euc(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_nor(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def I2form(t, sign=-1):
    R = t.resolvent(t.lam)
    return t.tr(t.Phi @ R @ t.Phi @ R) + sign * 2 * t.tr(t.X.T @ R @ t.X)


@claim("s88h2-factor", kind="id", section="8", sizes=ANY)
def factor(s):
    """𝓛*(λ) = N + [−Xᵀ; Pᵀ] R [P, X] (TRUE)."""
    return {"L*": Ldual(s, s.X, s.P, s.lam) - (Nmat(s) + left(s) @ s.resolvent(s.lam) @ right(s))}


@claim("s88h2-factor-twin", kind="id", section="8", sizes=ANY)
def factor_twin(s):
    """FALSE twin: 𝓛*(λ) = N + [Xᵀ; Pᵀ] R [P, X]."""
    return {"L*": Ldual(s, s.X, s.P, s.lam) - (Nmat(s) + left(s, 1) @ s.resolvent(s.lam) @ right(s))}


def _expansion(s, sign):
    L = Ldual(s, s.X, s.P, s.lam)
    K = s.X.T @ s.P
    M1 = block([[sign * K, -s.Ir], [s.P.T @ s.P, s.P.T @ s.X]])
    return {"lambda(L*-N)": s.lam * (L - Nmat(s)) - (M1 + left(s) @ s.A @ s.resolvent(s.lam) @ right(s))}


@claim("s88h2-lambda-expansion", kind="id", section="8", sizes=ANY)
def lambda_expansion(s):
    """λ(𝓛* − N) = [[−XᵀP, −I], [PᵀP, PᵀX]] + [−Xᵀ; Pᵀ]AR[P, X] (TRUE)."""
    return _expansion(s, -1)


@claim("s88h2-lambda-expansion-twin", kind="id", section="8", sizes=R2UP)
def lambda_expansion_twin(s):
    """FALSE twin (r ≥ 2): upper-left block +XᵀP."""
    return _expansion(s, 1)


@claim("s88h2-trace-square", kind="id", section="8", sizes=ANY)
def trace_square(s):
    """tr 𝓛*(λ)² = tr(ΦRΦR) − 2tr(XᵀRX) (TRUE)."""
    L = Ldual(s, s.X, s.P, s.lam)
    return {"tr L*^2": s.tr(L @ L) - I2form(s)}


@claim("s88h2-trace-square-twin", kind="id", section="8", sizes=ANY)
def trace_square_twin(s):
    """FALSE twin: tr 𝓛*(λ)² = tr(ΦRΦR) + 2tr(XᵀRX)."""
    L = Ldual(s, s.X, s.P, s.lam)
    return {"tr L*^2": s.tr(L @ L) - I2form(s, 1)}


def _det_r1(s, sign):
    R = s.resolvent(s.lam)
    x, p = s.X, s.P
    L = Ldual(s, x, p, s.lam)
    xRx, xRp, pRp = s.tr(x.T @ R @ x), s.tr(x.T @ R @ p), s.tr(p.T @ R @ p)
    return {"det L* - disc": det(s, L) - (xRx * (1 + pRp) + sign * xRp * xRp),
            "det L* + tr L*^2/2": det(s, L) + s.tr(L @ L) / 2}


@claim("s88h2-det-r1", kind="id", section="8", sizes=R1)
def det_r1(s):
    """r = 1: det 𝓛* = (xᵀRx)(1 + pᵀRp) − (xᵀRp)² = −½tr 𝓛*² (TRUE)."""
    return _det_r1(s, -1)


@claim("s88h2-det-r1-twin", kind="id", section="8", sizes=R1N2)
def det_r1_twin(s):
    """FALSE twin: + (xᵀRp)² (the second residual is true; the claim fails on the first)."""
    return _det_r1(s, 1)


def _tangent(s, unit):
    V, B = Vmat(s, s.X, s.P), Bmat(s, s.lam)
    M = V.T @ B @ V
    adj = s.mat([[M[1, 1], -M[0, 1]], [-M[1, 0], M[0, 0]]], ("r+r", "r+r"))
    e1 = s.mat([[s.q(1)], [s.q(0)]], ("r+r", "?"))
    eu = s.mat([[s.q(1)], [s.q(0)]] if unit == 0 else [[s.q(0)], [s.q(1)]], ("r+r", "?"))
    w = V @ adj @ e1
    dM = det(s, M)
    return {"V^T B w - det(M) e": V.T @ B @ w - dM * eu,
            "<w,Bw> - det(M) adj11": s.tr(w.T @ B @ w) - dM * adj[0, 0]}


@claim("s88h2-tangent-vector-r1", kind="geo", section="8", sizes=R1)
def tangent_vector_r1(s):
    """r = 1: w = 𝒱 adj(M)E₁: 𝒱ᵀBw = det(M)E₁ and ⟨w, Bw⟩ = det(M)adj(M)₁₁ (TRUE)."""
    return _tangent(s, 0)


@claim("s88h2-tangent-vector-r1-twin", kind="geo", section="8", sizes=R1)
def tangent_vector_r1_twin(s):
    """FALSE twin: 𝒱ᵀBw = det(M)E₂."""
    return _tangent(s, 1)


def _cb(s, sign):
    K = s.X.T @ s.P
    e = elementary(s, s.Phi, 2 * s.r)
    return {"e_2r(Phi) - det(UᵀU)": e[2 * s.r] - det(s, s.P.T @ s.P + sign * K @ K)}


@claim("s88h2-cauchy-binet", kind="id", section="8", sizes=TWO_R_LE_N)
def cauchy_binet(s):
    """e_{2r}(Φ) = det(PᵀP + K²) = det(UᵀU) = Σ_I det(U_I)² (TRUE, 2r ≤ n)."""
    return _cb(s, 1)


@claim("s88h2-cauchy-binet-twin", kind="id", section="8", sizes=TWO_R_LE_N_R2)
def cauchy_binet_twin(s):
    """FALSE twin (r ≥ 2): e_{2r}(Φ) = det(PᵀP − K²)."""
    return _cb(s, -1)


@claim("s88h2-symplectic", kind="id", section="8", sizes=ANY)
def symplectic(s):
    """𝓛*ᵀJ + J𝓛* = 0 (TRUE)."""
    L, Jm = Ldual(s, s.X, s.P, s.lam), Jmat(s)
    return {"L^T J + J L": L.T @ Jm + Jm @ L}


@claim("s88h2-symplectic-twin", kind="id", section="8", sizes=ANY)
def symplectic_twin(s):
    """FALSE twin: 𝓛*ᵀJ − J𝓛* = 0."""
    L, Jm = Ldual(s, s.X, s.P, s.lam), Jmat(s)
    return {"L^T J - J L": L.T @ Jm - Jm @ L}


@claim("s88h2-trace-conserved", kind="pb", section="8", sizes=ANY)
def trace_conserved(s):
    """tr(ΦRΦR) − 2tr(XᵀRX) is conserved along (NE_XP) and (N0_XP2) (TRUE)."""
    return {"NE_XP": s.d(I2form, s.dirac_flow(H_euc)), "N0_XP2": s.d(I2form, s.dirac_flow(H_nor))}


@claim("s88h2-trace-conserved-twin", kind="pb", section="8", sizes=RLTN)
def trace_conserved_twin(s):
    """FALSE twin: tr(ΦRΦR) + 2tr(XᵀRX) conserved along (NE_XP)."""
    return {"NE_XP": s.d(lambda t: I2form(t, 1), s.dirac_flow(H_euc))}


def _resolvent(s, sign):
    mu = s.scalar("mu")
    L1, L2 = Ldual(s, s.X, s.P, s.lam), Ldual(s, s.X, s.P, mu)
    return {"L(lam)-L(mu)": L1 - L2 - sign * (mu - s.lam) * (left(s) @ s.resolvent(s.lam) @ s.resolvent(mu) @ right(s))}


@claim("s88h2-resolvent", kind="id", section="8", sizes=ANY)
def resolvent_identity(s):
    """𝓛*(λ) − 𝓛*(μ) = (μ − λ)[−Xᵀ; Pᵀ]R(λ)R(μ)[P, X] (TRUE)."""
    return _resolvent(s, 1)


@claim("s88h2-resolvent-twin", kind="id", section="8", sizes=ANY)
def resolvent_identity_twin(s):
    """FALSE twin: (λ − μ) instead of (μ − λ)."""
    return _resolvent(s, -1)


@claim("s88h2-rank-C", kind="dim", section="8", sizes=ANY)
def rank_C(s):
    """rank(𝓛*(λ) − N) = min(n, 2r) generically (TRUE)."""
    C = Ldual(s, s.X, s.P, s.lam) - Nmat(s)
    return {"rank": Rank(C, min(int(s.n), 2 * int(s.r)))}


@claim("s88h2-rank-C-twin", kind="dim", section="8", sizes=N_LT_2R)
def rank_C_twin(s):
    """FALSE twin (n < 2r): rank 2r."""
    C = Ldual(s, s.X, s.P, s.lam) - Nmat(s)
    return {"rank": Rank(C, 2 * int(s.r))}


@claim("s88h2-rank-V", kind="dim", section="8", sizes=ANY)
def rank_V(s):
    """rank 𝒱 = 2r at every point (TRUE)."""
    return {"rank": Rank(Vmat(s, s.X, s.P), 2 * int(s.r), generic=False)}


@claim("s88h2-rank-V-twin", kind="dim", section="8", sizes=ANY)
def rank_V_twin(s):
    """FALSE twin: rank 𝒱 = 2r − 1 generically."""
    return {"rank": Rank(Vmat(s, s.X, s.P), 2 * int(s.r) - 1)}


def _rotation(s, transpose):
    eta = s.eta
    Q = (s.Ir - eta) @ (s.Ir + eta).inv()
    Bt = Q.T
    zn = s.zeros(s.n, s.r, ("n", "r"))
    z = s.zeros(s.r, s.r, ("r", "r"))
    lhs = Vmat(s, s.X @ Q, s.P @ Q) @ block([[Bt, z], [z, Bt]])
    G = Bt if transpose else Q
    rhs = block([[s.In, zn], [zn.T, G]]) @ Vmat(s, s.X, s.P)
    return {"V(XB,PB) diag(B^T,B^T) - diag(I,B^T) V": lhs - rhs}


@claim("s88h2-rotation", kind="geo", section="8", sizes=ANY)
def rotation(s):
    """𝒱(XB, PB)diag(Bᵀ, Bᵀ) = diag(I_n, Bᵀ)𝒱(X, P), B Cayley of η ∈ so(r) (TRUE)."""
    return _rotation(s, True)


@claim("s88h2-rotation-twin", kind="geo", section="8", sizes=R2UP)
def rotation_twin(s):
    """FALSE twin (r ≥ 2): … = diag(I_n, B)𝒱(X, P)."""
    return _rotation(s, False)


@claim("s88h2-rotation-det", kind="geo", section="8", sizes=admissible(n_max=3, r_max=2))
def rotation_det(s):
    """det M(XB, PB) = det M(X, P), M = 𝒱ᵀB(λ)𝒱 (TRUE: 𝒱(XB,PB) = diag(I, Bᵀ)𝒱 diag(B, B))."""
    eta = s.eta
    Q = (s.Ir - eta) @ (s.Ir + eta).inv()
    Bl = Bmat(s, s.lam)
    V0, V1 = Vmat(s, s.X, s.P), Vmat(s, s.X @ Q, s.P @ Q)
    return {"det": det(s, V1.T @ Bl @ V1) - det(s, V0.T @ Bl @ V0)}


def _F(s):
    x, p, a = s.X, s.P, s.a
    n = int(s.n)
    Fs = []
    for i in range(n):
        acc = x[i, 0] * x[i, 0]
        for j in range(n):
            if j != i:
                m = x[i, 0] * p[j, 0] - x[j, 0] * p[i, 0]
                acc = acc + m * m / (a[i] - a[j])
        Fs.append(acc)
    return Fs


def _uhl(s, half):
    Fs, a = _F(s), s.a
    tot, wtot = s.q(0), s.q(0)
    for i, F in enumerate(Fs):
        tot = tot + F
        wtot = wtot + a[i] * F
    pp = s.tr(s.P.T @ s.P)
    return {"sum F - 1": tot - 1,
            "sum a F - 2H": wtot - (s.tr(s.X.T @ s.A @ s.X) + (pp / 2 if half else pp))}


@claim("s88h2-uhlenbeck-sums", kind="id", section="8", sizes=R1)
def uhlenbeck_sums(s):
    """r = 1: ΣF_i = 1, Σa_iF_i = xᵀAx + pᵀp (TRUE)."""
    return _uhl(s, False)


@claim("s88h2-uhlenbeck-sums-twin", kind="id", section="8", sizes=R1N2)
def uhlenbeck_sums_twin(s):
    """FALSE twin: Σa_iF_i = xᵀAx + ½pᵀp."""
    return _uhl(s, True)


def _adj(s, M, m):
    """The adjugate of an m×m matrix of the scene from its cofactors (det of (m−1)×(m−1) minors)."""
    rows = []
    for i in range(m):
        row = []
        for j in range(m):
            sub = [[M[a, b] for b in range(m) if b != i] for a in range(m) if a != j]
            c = det(s, s.mat(sub, ("?", "?")))
            row.append(c if (i + j) % 2 == 0 else -c)
        rows.append(row)
    return s.mat(rows, ("r+r", "r+r"))


def _tangent2(s, twin):
    m = 2 * int(s.r)
    V, B = Vmat(s, s.X, s.P), Bmat(s, s.lam)
    M = V.T @ B @ V
    adj = _adj(s, M, m)
    e1 = s.mat([[s.q(1)]] + [[s.q(0)] for _ in range(m - 1)], ("r+r", "?"))
    eu = s.mat([[s.q(0)], [s.q(1)]] + [[s.q(0)] for _ in range(m - 2)], ("r+r", "?")) if twin else e1
    w = V @ adj @ e1
    dM = det(s, M)
    return {"V^T B w - det(M) e": V.T @ B @ w - dM * eu,
            "<w,Bw> - det(M) adj11": s.tr(w.T @ B @ w) - dM * adj[0, 0]}


@claim("s88h2-tangent-vector-r2", kind="geo", section="8", sizes=[(2, 2), (3, 2), (4, 2)])
def tangent_vector_r2(s):
    """r = 2: w = 𝒱 adj(M)E₁ (adjugate from cofactors): 𝒱ᵀBw = det(M)E₁, ⟨w, Bw⟩ = det(M)adj(M)₁₁ (TRUE)."""
    return _tangent2(s, False)


@claim("s88h2-tangent-vector-r2-twin", kind="geo", section="8", sizes=[(2, 2), (3, 2), (4, 2)])
def tangent_vector_r2_twin(s):
    """FALSE twin: 𝒱ᵀBw = det(M)E₂."""
    return _tangent2(s, True)
