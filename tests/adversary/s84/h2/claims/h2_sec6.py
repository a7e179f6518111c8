"""h2 hidden statements from §6 (Compatible Poisson brackets and integrability).
Truth: by hand (below) and numerically by ../truth_numpy.py (logs/truth_numpy*.log).
Conventions: <a, b> = −½tr(ab) on gl(n); a covector y = ξ + η (ξ skew, η sym); Λ1, Λ2 of (LAMBDA12) are written
out here by hand from the paper, not taken from stiefelsym.brackets.

T10 h2-pencil-endpoint-casimirs (TRUE): tr v^k (v = sym x) are Casimirs of Λ1 (gradient −2k v^{k−1} ∈ Sym,
    Λ1(η, ·)|x = <x, [η, ζ]> = <v, [η, ζ]> = <[v, η], ζ> = 0), and tr(x − A)^k are Casimirs of Λ2 (gradient
    −2k(x−A)^{k−1}; <x−A, [(x−A)^{k−1}, b]> = 0); k = 2, 3 at a generic x ∈ gl(n), generic b.
    -twin (FALSE, n >= 2): tr(x + A)^k is a Casimir of Λ2.
T11 h2-lambda-1m1 (TRUE): (LAMBDA): Λ_{1,−1}(ξ+η, ζ+θ)|_{h+v} = −<h,[η,θ]> + <A,[ξ,θ] + [η,ζ]> (Λ1 − Λ2: the
    [ξ,ζ] and [η,θ] terms pair to 0 with A, ∈ Sym, and <x,[η,θ]> = <h,[η,θ]>).  -twin (FALSE, n >= 2): +<h,[η,θ]>.
T12 h2-a1-rank (TRUE, dim): (A1)/(L3),(L4): at x = Θ(X,P), y ↦ Λ_{1,−1}(y, ·) = [A,η] + [A,ξ] − [h,η] has rank
    n² − n (kernel: η diagonal, ξ = ad_A⁻¹[h,η]).  -twin (FALSE, r < n... stated for n >= 2): rank n² − r, r < n.
T13 h2-lema1-rank (TRUE, dim, Lemma LEMA1, (dimension)): at x = Θ(X,P), y ↦ Λ1(y, ·) = [x, ξ] + [v, η] has rank
    2l = 2r(n−r) + r(r−1)/2 − [r/2].  -twin (FALSE, r >= 2): rank 2r(n−r) + r(r−1)/2 (the [r/2] dropped).
T14 h2-theta-image-dim (TRUE, dim): Θ has rank 2dim V − dim SO(r) on T*V (SO(r)-invariant, a finite covering of
    its image on the quotient): rank[dΘ; d(cond_XP)] = 2dim V − r(r−1)/2 + r(r+1).
    -twin (FALSE, r >= 2): rank 2dim V + r(r+1) (Θ an immersion).
T15 h2-jk-casimirs (TRUE, pb): J_1 = tr Ψ² commutes with the SO(r)-invariant functions tr((PᵀP)²) and
    tr(L(λ)²) (perelomov); -twin (FALSE, 2 <= r <= n−1): {tr Ψ², tr(S PᵀP)} = 0.
    h2-jk-rank (TRUE, dim, r >= 2): J_1..J_[r/2] are independent: rank[dJ; d(cond_XP)] = [r/2] + r(r+1).
    -twin (FALSE, r >= 2): J_1..J_{[r/2]+1} independent (rank [r/2] + 1 + r(r+1)).
T16 h2-hneum-theta (TRUE, Remark after NEUMANN for every κ): H_neum,κ = H∘Θ + κ/2<Ψ,Ψ>, H = ½<h,h> − <A,v>.
    -twin (FALSE): + <A, v>.
T22 h2-lambda-1m1-rank-everywhere (TRUE, dim): Λ_{1,−1} has rank n² − n at a generic x ∈ gl(n) and at x = 0 (the
    block <[A,ξ], θ> is x-independent, ξ ↦ [A,ξ] injective), so at λ1 + λ2 = 0 the pencil bracket is NOT isomorphic
    to the gl(n) Lie–Poisson bracket (rank 0 at 0), as §6's "For λ2 ≠ 0, ... isomorphic" literally says.
    -twin (FALSE): rank 0 at x = 0.
T23 h2-theta-reflection (TRUE): Θ(XQ, PQ) = Θ(X, P) for the reflection Q = diag(−1,1,…,1) ∈ O(r)∖SO(r) (the Z2 of
    the covering θ; for even r, (−X,−P) is already in the SO(r)-orbit).  -twin (FALSE, r >= 2): Ψ invariant too.
"""
from stiefelsym import Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, matrix_units

N = 4


def skew(M):
    return (M - M.T) / 2


def sym(M):
    return (M + M.T) / 2


def L1(s, x, y, z):
    """Λ1(ξ+η, ζ+θ)|x = <x, [ξ,ζ] + [ξ,θ] + [η,ζ]> (LAMBDA12)."""
    xi, eta, ze, th = skew(y), sym(y), skew(z), sym(z)
    return s.killing(x, comm(xi, ze) + comm(xi, th) + comm(eta, ze))


def L2(s, x, y, z):
    """Λ2(y, z)|x = <x − A, [y, z]>."""
    return s.killing(x - s.A, comm(y, z))


def power(M, k):
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return acc


# ---------------------------------------------------------------- T10
@claim("h2-pencil-endpoint-casimirs", kind="pb", section="6", sizes=admissible(n_max=N))
def endpoint_casimirs(s):
    """TRUE: Λ1(∇tr v^k, b) = 0, Λ2(∇tr(x−A)^k, b) = 0, k = 2, 3."""
    x, b = s.generic("x", "n", "n"), s.generic("b", "n", "n")
    out = {}
    for k in (2, 3):
        out[f"L1 tr v^{k}"] = L1(s, x, (-2 * k) * power(sym(x), k - 1), b)
        out[f"L2 tr(x-A)^{k}"] = L2(s, x, (-2 * k) * power(x - s.A, k - 1), b)
    return out


@claim("h2-pencil-endpoint-casimirs-twin", kind="pb", section="6", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def endpoint_casimirs_twin(s):
    """FALSE: Λ2(∇tr(x+A)^k, b) = 0."""
    x, b = s.generic("x", "n", "n"), s.generic("b", "n", "n")
    return {f"L2 tr(x+A)^{k}": L2(s, x, (-2 * k) * power(x + s.A, k - 1), b) for k in (2, 3)}


# ---------------------------------------------------------------- T11
def _lambda_parts(s):
    h = s.xi
    v = s.generic("V", "n", "n", "sym")
    y, z = s.generic("y", "n", "n"), s.generic("z", "n", "n")
    return h, v, y, z


@claim("h2-lambda-1m1", kind="id", section="6", sizes=admissible(n_max=N))
def lambda_1m1(s):
    """TRUE: (Λ1 − Λ2)(y, z)|_{h+v} = −<h,[η,θ]> + <A,[ξ,θ] + [η,ζ]>."""
    h, v, y, z = _lambda_parts(s)
    x = h + v
    rhs = -s.killing(h, comm(sym(y), sym(z))) + s.killing(s.A, comm(skew(y), sym(z)) + comm(sym(y), skew(z)))
    return {"LAMBDA": L1(s, x, y, z) - L2(s, x, y, z) - rhs}


@claim("h2-lambda-1m1-twin", kind="id", section="6", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def lambda_1m1_twin(s):
    """FALSE: + <h,[η,θ]>."""
    h, v, y, z = _lambda_parts(s)
    x = h + v
    rhs = s.killing(h, comm(sym(y), sym(z))) + s.killing(s.A, comm(skew(y), sym(z)) + comm(sym(y), skew(z)))
    return {"LAMBDA": L1(s, x, y, z) - L2(s, x, y, z) - rhs}


# ---------------------------------------------------------------- T12, T13
def _gl_rank(s, f):
    return matrix_of(s, f, matrix_units(s, "n", "n"))


def F_1m1(s):
    h = s.Phi

    def f(y):
        return comm(s.A, sym(y)) + comm(s.A, skew(y)) - comm(h, sym(y))
    return f


def F_1(s):
    x, v = s.Phi + s.X @ s.X.T, s.X @ s.X.T

    def f(y):
        return comm(x, skew(y)) + comm(v, sym(y))
    return f


@claim("h2-a1-rank", kind="dim", section="6", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def a1_rank(s):
    """TRUE: rank of y ↦ Λ_{1,−1}(y,·) at Θ(X,P) is n² − n; the map represents Λ1 − Λ2 (residual)."""
    n = s.n
    z = s.generic("z", "n", "n")
    y = s.generic("y", "n", "n")
    x = s.Phi + s.X @ s.X.T
    return {"rank": Rank(_gl_rank(s, F_1m1(s)), n * n - n),
            "represents": L1(s, x, y, z) - L2(s, x, y, z) - s.killing(F_1m1(s)(y), z)}


@claim("h2-a1-rank-twin", kind="dim", section="6", sizes=admissible(n_max=N, n_min=2, where=lambda n, r: r < n, condition="r < n"))
def a1_rank_twin(s):
    """FALSE (r < n): rank n² − r."""
    return {"rank": Rank(_gl_rank(s, F_1m1(s)), s.n * s.n - s.r)}


def two_l(n, r):
    return 2 * r * (n - r) + r * (r - 1) // 2 - r // 2


@claim("h2-lema1-rank", kind="dim", section="6", sizes=admissible(n_max=N))
def lema1_rank(s):
    """TRUE: rank Λ1 at Θ(X,P) = 2r(n−r) + r(r−1)/2 − [r/2]; the map represents Λ1 (residual)."""
    z, y = s.generic("z", "n", "n"), s.generic("y", "n", "n")
    x = s.Phi + s.X @ s.X.T
    return {"rank": Rank(_gl_rank(s, F_1(s)), two_l(s.n, s.r)),
            "represents": L1(s, x, y, z) - s.killing(F_1(s)(y), z)}


@claim("h2-lema1-rank-twin", kind="dim", section="6", sizes=admissible(n_max=N, r_min=2, condition="r >= 2"))
def lema1_rank_twin(s):
    """FALSE (r >= 2): rank 2r(n−r) + r(r−1)/2."""
    n, r = s.n, s.r
    return {"rank": Rank(_gl_rank(s, F_1(s)), 2 * r * (n - r) + r * (r - 1) // 2)}


# ---------------------------------------------------------------- T14
def Theta(t):
    return t.P @ t.X.T - t.X @ t.P.T + t.X @ t.X.T


def cons(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def dimV(n, r):
    return r * n - r * (r + 1) // 2


@claim("h2-theta-image-dim", kind="dim", section="6", sizes=admissible(n_max=N))
def theta_image_dim(s):
    """TRUE: rank[dΘ; dF] = 2dim V − r(r−1)/2 + r(r+1)."""
    n, r = s.n, s.r
    M = s.mat(s.jacobian(Theta) + s.jacobian(cons))
    return {"rank": Rank(M, 2 * dimV(n, r) - r * (r - 1) // 2 + r * (r + 1))}


@claim("h2-theta-image-dim-twin", kind="dim", section="6", sizes=admissible(n_max=N, r_min=2, condition="r >= 2"))
def theta_image_dim_twin(s):
    """FALSE (r >= 2): rank[dΘ; dF] = 2dim V + r(r+1)."""
    n, r = s.n, s.r
    M = s.mat(s.jacobian(Theta) + s.jacobian(cons))
    return {"rank": Rank(M, 2 * dimV(n, r) + r * (r + 1))}


# ---------------------------------------------------------------- T15
def J1(t):
    return t.tr(t.Psi @ t.Psi)


def per2(t):
    L = t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
    return t.tr(L @ L)


@claim("h2-jk-casimirs", kind="pb", section="6", sizes=admissible(n_max=N))
def jk_casimirs(s):
    """TRUE: {tr Ψ², tr((PᵀP)²)} = 0, {tr Ψ², tr L(λ)²} = 0."""
    return {"{J1, tr (P^TP)^2}": s.bracket(J1, lambda t: t.tr(t.P.T @ t.P @ t.P.T @ t.P)),
            "{J1, perelomov_2}": s.bracket(J1, per2)}


@claim("h2-jk-casimirs-twin", kind="pb", section="6",
       sizes=admissible(n_max=N, r_min=2, where=lambda n, r: r < n, condition="2 <= r <= n - 1"))
def jk_casimirs_twin(s):
    """FALSE (2 <= r <= n−1): {tr Ψ², tr(S PᵀP)} = 0."""
    return {"{J1, trSPP}": s.bracket(J1, lambda t: t.tr(t.generic("S", "r", "r", "sym") @ t.P.T @ t.P))}


def Jfun(k):
    def f(t):
        return t.tr(power(t.Psi, 2 * k))
    return f


def _jk_matrix(s, m):
    rows = []
    for k in range(1, m + 1):
        rows += s.jacobian(Jfun(k))
    return s.mat(rows + s.jacobian(cons))


@claim("h2-jk-rank", kind="dim", section="6", sizes=admissible(n_max=N, r_min=2, condition="r >= 2"))
def jk_rank(s):
    """TRUE (r >= 2): rank[dJ_1..dJ_[r/2]; dF] = [r/2] + r(r+1)."""
    r = s.r
    return {"rank": Rank(_jk_matrix(s, r // 2), r // 2 + r * (r + 1))}


@claim("h2-jk-rank-twin", kind="dim", section="6", sizes=admissible(n_max=N, r_min=2, condition="r >= 2"))
def jk_rank_twin(s):
    """FALSE (r >= 2): rank[dJ_1..dJ_{[r/2]+1}; dF] = [r/2] + 1 + r(r+1)."""
    r = s.r
    return {"rank": Rank(_jk_matrix(s, r // 2 + 1), r // 2 + 1 + r * (r + 1))}


# ---------------------------------------------------------------- T16
def H_k(t):
    W = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(W @ W) + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("h2-hneum-theta", kind="id", section="6", sizes=admissible(n_max=5))
def hneum_theta(s):
    """TRUE: H_neum,κ = ½<h,h> − <A,v> + κ/2<Ψ,Ψ> at h + v = Θ."""
    h, v = s.Phi, s.X @ s.X.T
    return {"H": H_k(s) - (s.killing(h, h) / 2 - s.killing(s.A, v) + s.kappa * s.killing(s.Psi, s.Psi) / 2)}


@claim("h2-hneum-theta-twin", kind="id", section="6", sizes=admissible(n_max=5))
def hneum_theta_twin(s):
    """FALSE: H_neum,κ = ½<h,h> + <A,v> + κ/2<Ψ,Ψ>."""
    h, v = s.Phi, s.X @ s.X.T
    return {"H": H_k(s) - (s.killing(h, h) / 2 + s.killing(s.A, v) + s.kappa * s.killing(s.Psi, s.Psi) / 2)}


# ---------------------------------------------------------------- T22 (paper: "For λ2 ≠ 0 ... isomorphic to gl(n)")
def F_1m1_at(s, h):
    def f(y):
        return comm(s.A, sym(y)) + comm(s.A, skew(y)) - comm(h, sym(y))
    return f


@claim("h2-lambda-1m1-rank-everywhere", kind="dim", section="6", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def lambda_1m1_rank_everywhere(s):
    """TRUE: Λ_{1,−1} = Λ1 − Λ2 has rank n² − n at a generic x = h + v ∈ gl(n) and at x = 0 (its block
    <[A,ξ], θ> does not depend on x and ξ ↦ [A,ξ] is injective on so(n)): so Λ_{λ1,λ2} with λ1 + λ2 = 0 is not
    isomorphic to the Lie–Poisson bracket of gl(n) (rank 0 at 0), contrary to the literal "For λ2 ≠ 0" of §6."""
    n = s.n
    return {"rank at generic h": Rank(_gl_rank(s, F_1m1_at(s, s.xi)), n * n - n),
            "rank at x = 0": Rank(_gl_rank(s, F_1m1_at(s, s.zeros(n, n, ("n", "n")))), n * n - n)}


@claim("h2-lambda-1m1-rank-everywhere-twin", kind="dim", section="6", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def lambda_1m1_rank_everywhere_twin(s):
    """FALSE: Λ_{1,−1} has rank 0 at x = 0 (as a Lie–Poisson bracket would)."""
    n = s.n
    return {"rank at x = 0": Rank(_gl_rank(s, F_1m1_at(s, s.zeros(n, n, ("n", "n")))), 0)}


# ---------------------------------------------------------------- T23 (Θ is O(r)-invariant: the Z2 of the covering θ)
def Qr(s):
    r = s.r
    return s.mat([[(s.q(-1) if i == 0 else s.q(1)) if i == j else s.q(0) for j in range(r)] for i in range(r)], ("r", "r"))


@claim("h2-theta-reflection", kind="id", section="6", sizes=admissible(n_max=5))
def theta_reflection(s):
    """TRUE: Θ(XQ, PQ) = Θ(X, P) for the reflection Q = diag(−1, 1, …, 1) ∈ O(r) \\ SO(r) (Θ is O(r)-invariant;
    for even r, (X,P) ↦ (−X,−P) lies in SO(r) and the Z2 of the covering θ is this reflection)."""
    Q = Qr(s)
    X, P = s.X @ Q, s.P @ Q
    return {"Theta": (P @ X.T - X @ P.T + X @ X.T) - Theta(s)}


@claim("h2-theta-reflection-twin", kind="id", section="6", sizes=admissible(n_max=5, r_min=2, condition="r >= 2"))
def theta_reflection_twin(s):
    """FALSE (r >= 2): Ψ(XQ, PQ) = Ψ(X, P) for the same reflection (Ψ ↦ QΨQ)."""
    Q = Qr(s)
    X, P = s.X @ Q, s.P @ Q
    return {"Psi": (X.T @ P - P.T @ X) - s.Psi}
