"""Probes of the free letters S, D, C, Dn and of a resolvent at a moving spectral parameter, combined where
their rules do not reach (second round)."""
from stiefelsym import admissible, claim, twisted


def _S(s):
    return twisted.reflection(s)


def _Dn(s):
    return twisted.eigenspace_projector(s)


def _DC(s):
    return twisted.block_projector(s, 0), twisted.block_projector(s, 1)


@claim("s32-refl-metric", kind="id", sizes=admissible(n_max=3), realization="metric", statement="S A = A S (metric)")
def refl_metric(s):
    """True: S commutes with A in the metric realization too."""
    S = _S(s)
    return {"r": S @ s.A - s.A @ S}


@claim("s32-refl-metric-flow", kind="id", sizes=admissible(n_max=3), realization="metric",
       statement="{tr(X^T S X), H} = 2 tr(Xdot^T S X) (metric)")
def refl_metric_flow(s):
    """True control of the metric realization with S inside a function."""
    def H(t):
        return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2
    flow = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.X.T @ _S(t) @ t.X), flow) - 2 * s.tr(flow.Xdot.T @ _S(s) @ s.X)}


@claim("s32-refl-Ainv", kind="id", sizes=admissible(n_max=3), statement="S A^-1 = A^-1 S")
def refl_ainv(s):
    """True: S commutes with A, so with A^-1."""
    S = _S(s)
    return {"r": S @ s.Ainv - s.Ainv @ S}


@claim("s32-refl-Ainv-false", kind="id", sizes=admissible(n_max=3), statement="S A^-1 X = A^-1 X")
def refl_ainv_false(s):
    """False."""
    return {"r": _S(s) @ s.Ainv @ s.X - s.Ainv @ s.X}


@claim("s32-Dn-eigenspace", kind="id", sizes=admissible(n_max=3),
       statement="Dn A2 = A2 Dn, A2 = lam Dn + (I - Dn) A (I - Dn)")
def dn_eigenspace(s):
    """True for every orthogonal projector Dn."""
    D = _Dn(s)
    A2 = D * s.lam + (s.In - D) @ s.A @ (s.In - D)
    return {"r": D @ A2 - A2 @ D}


@claim("s32-Dn-eigenspace-false", kind="id", sizes=admissible(n_max=3),
       statement="A2 Dn = lam I, A2 = lam Dn + (I - Dn) A (I - Dn)")
def dn_eigenspace_false(s):
    """False (it is lam Dn)."""
    D = _Dn(s)
    A2 = D * s.lam + (s.In - D) @ s.A @ (s.In - D)
    return {"r": A2 @ D - s.In * s.lam}


@claim("s32-two-projectors-DnS", kind="id", sizes=admissible(n_max=3), statement="(Dn S)^2 = Dn")
def two_projectors(s):
    """True at the fixed sizes only (S_1 and diag(I_2, 0) commute), not for every S, Dn."""
    M = _Dn(s) @ _S(s)
    return {"r": M @ M - _Dn(s)}


@claim("s32-split-traces", kind="id", sizes=admissible(n_max=3), statement="tr D + tr C = r")
def split_traces(s):
    """True at the fixed sizes only (D + C = I_r there)."""
    D, C = _DC(s)
    return {"r": s.tr(D) + s.tr(C) - s.tr(s.Ir)}


@claim("s32-split-traces-false", kind="id", sizes=admissible(n_max=3), statement="tr D = tr C")
def split_traces_false(s):
    """False at odd r."""
    D, C = _DC(s)
    return {"r": s.tr(D) - s.tr(C)}


@claim("s32-split-r1-C-zero", kind="id", sizes=admissible(n_max=3, r_max=1), statement="C = 0 at r = 1")
def split_r1(s):
    """True at r = 1 (C = diag(I_0) = 0), not a consequence of the letters' rules."""
    _, C = _DC(s)
    return {"r": C}


@claim("s32-split-r1-D-zero", kind="id", sizes=admissible(n_max=3, r_max=1), statement="D = 0 at r = 1")
def split_r1_false(s):
    """False at r = 1 (D = 1)."""
    D, _ = _DC(s)
    return {"r": D}


@claim("s32-split-r2-D-E1", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2), statement="D = E1 E1^T at r = 2")
def split_r2(s):
    """True at r = 2 (D = diag(1, 0)), not a consequence of the letters' rules."""
    D, _ = _DC(s)
    E1 = twisted.basis_vector(s, 0)
    return {"r": D - E1 @ E1.T}


@claim("s32-split-r2-D-E2", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2), statement="D = E2 E2^T at r = 2")
def split_r2_false(s):
    """False at r = 2."""
    D, _ = _DC(s)
    E2 = twisted.basis_vector(s, 1)
    return {"r": D - E2 @ E2.T}


@claim("s32-split-r2-D-plus-C", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2), statement="D + C = I at r = 2")
def split_r2_sum(s):
    """True at r = 2 (the blocks are R^1 + R^1), not a consequence of the letters' rules."""
    D, C = _DC(s)
    return {"r": D + C - s.Ir}


@claim("s32-split-r2-rank-one", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2),
       statement="D M D = tr(D M) D at r = 2 (D of rank one)")
def split_r2_rank_one(s):
    """True at r = 2 (D = E1 E1^T has rank 1): D (X^T A X) D = tr(D X^T A X) D."""
    D, _ = _DC(s)
    M = s.X.T @ s.A @ s.X
    return {"r": D @ M @ D - s.tr(D @ M) * D}


@claim("s32-split-square", kind="id", sizes=admissible(n_max=3, r_is_n=True, where=lambda n, r: r == n),
       statement="X D X^T + X C X^T = I_n at r = n")
def split_square(s):
    """True at r = n for D + C = I_r (the fixed sizes), not for every pair of orthogonal blocks."""
    D, C = _DC(s)
    return {"r": s.X @ D @ s.X.T + s.X @ C @ s.X.T - s.In}


@claim("s32-split-square-conj", kind="id", sizes=admissible(n_max=3, r_is_n=True, where=lambda n, r: r == n),
       statement="(X D X^T)^2 = X D X^T, X D X^T X C X^T = 0 at r = n")
def split_square_conj(s):
    """True for every pair of orthogonal blocks (X^T X = I)."""
    D, C = _DC(s)
    M, N = s.X @ D @ s.X.T, s.X @ C @ s.X.T
    return {"MM - M": M @ M - M, "MN": M @ N}


def _H(t):
    return (t.tr(t.P.T @ t.P) + t.tr(t.X.T @ t.A @ t.X)) / 2


@claim("s32-refl-at-point", kind="id", sizes=admissible(n_max=3), statement="H(SX, SP) = H(X, P)")
def refl_at_point(s):
    """True: S is orthogonal and commutes with A, so the Neumann Hamiltonian is S-invariant."""
    S = _S(s)
    t = twisted.at_point(s, S @ s.X, S @ s.P)
    return {"r": _H(t) - _H(s)}


@claim("s32-refl-at-point-false", kind="id", sizes=admissible(n_max=3), statement="tr(X^T A S X) at (SX, SP) = tr(X^T A X)")
def refl_at_point_false(s):
    """False: tr(X^T S A S S X) = tr(X^T A S X), not tr(X^T A X)."""
    S = _S(s)
    t = twisted.at_point(s, S @ s.X, S @ s.P)
    return {"r": t.tr(t.X.T @ t.A @ _S(t) @ t.X) - s.tr(s.X.T @ s.A @ s.X)}


@claim("s32-refl-at-point-bracket", kind="id", sizes=admissible(n_max=3),
       statement="{tr(X^T S X), H} at (SX, SP) = {tr(X^T S X), H} at (X, P)")
def refl_at_point_bracket(s):
    """True (S-invariance of H and of tr(X^T S X))."""
    S = _S(s)
    t = twisted.at_point(s, S @ s.X, S @ s.P)
    F = lambda u: u.tr(u.X.T @ _S(u) @ u.X)   # noqa: E731
    return {"r": t.bracket(F, _H) - s.bracket(F, _H)}


@claim("s32-mu-lam-at-n3", kind="id", sizes=admissible(n_max=3),
       statement="R(mu) R(lam) (mu - lam) = R(lam) - R(mu), mu = lam + (n - 3) tr P^T P")
def mu_lam(s):
    """True everywhere (the resolvent identity); mu = lam at n = 3."""
    mu = s.lam + (s.tr(s.In) - 3) * s.tr(s.P.T @ s.P)
    R, Rl = s.resolvent(mu), s.resolvent(s.lam)
    return {"r": R @ Rl * (mu - s.lam) - Rl + R}


@claim("s32-mu-lam-equal", kind="id", sizes=admissible(n_max=3),
       statement="R(mu) = R(lam), mu = lam + (n - 3) tr P^T P")
def mu_lam_equal(s):
    """False at n < 3 (true at n = 3 only)."""
    mu = s.lam + (s.tr(s.In) - 3) * s.tr(s.P.T @ s.P)
    return {"r": s.resolvent(mu) - s.resolvent(s.lam)}


@claim("s32-mu-ainv", kind="id", sizes=admissible(n_max=3),
       statement="mu A^-1 R(mu) = A^-1 + R(mu), mu = (n - 3) tr P^T P")
def mu_ainv(s):
    """True everywhere R(mu) exists (mu = 0 at n = 3: R(0) = -A^-1)."""
    mu = (s.tr(s.In) - 3) * s.tr(s.P.T @ s.P)
    R = s.resolvent(mu)
    return {"r": s.Ainv @ R * mu - s.Ainv - R}


@claim("s32-mu-ainv-false", kind="id", sizes=admissible(n_max=3),
       statement="A^-1 R(mu) = A^-1 + R(mu), mu = (n - 3) tr P^T P")
def mu_ainv_false(s):
    """False (a factor mu dropped)."""
    mu = (s.tr(s.In) - 3) * s.tr(s.P.T @ s.P)
    R = s.resolvent(mu)
    return {"r": s.Ainv @ R - s.Ainv - R}


@claim("s32-mu-eigen-inside-gradient", kind="id", sizes=admissible(n_max=3),
       statement="grad_X tr(X^T (A R - R A) X) = 0, mu = tr(Dn A (I - S))/2")
def mu_eigen_gradient(s):
    """R(mu) exists at no point of any stated size (mu = a_1 there), built only inside a function."""
    def F(t):
        mu = (t.tr(_Dn(t) @ t.A) - t.tr(_Dn(t) @ t.A @ _S(t))) / 2
        R = t.resolvent(mu)
        return t.tr(t.X.T @ (t.A @ R - R @ t.A) @ t.X)
    gX, gP = s.gradient(F)
    return {"gX": gX, "gP": gP}


@claim("s32-mu-eigen-inside-derivative", kind="id", sizes=admissible(n_max=3),
       statement="d/dt tr(A R - R A) = 0 along the Neumann flow, mu = tr(Dn A (I - S))/2 + tr(X^T X) - r")
def mu_eigen_derivative(s):
    """R(mu) exists at no point of any stated size (mu = a_1 there), built only inside a function."""
    def F(t):
        mu = (t.tr(_Dn(t) @ t.A) - t.tr(_Dn(t) @ t.A @ _S(t))) / 2
        R = t.resolvent(mu)
        return t.tr(t.X.T @ (t.A @ R - R @ t.A) @ t.P)
    return {"r": s.d(F, s.dirac_flow(_H))}


@claim("s32-mu-eigen-inside-bracket", kind="id", sizes=admissible(n_max=3),
       statement="{tr(X^T (A R - R A) P), H} = 0, mu = tr(Dn A (I - S))/2")
def mu_eigen_bracket(s):
    """R(mu) exists at no point of any stated size (mu = a_1 there), built only inside a function."""
    def F(t):
        mu = (t.tr(_Dn(t) @ t.A) - t.tr(_Dn(t) @ t.A @ _S(t))) / 2
        R = t.resolvent(mu)
        return t.tr(t.X.T @ (t.A @ R - R @ t.A) @ t.P)
    return {"r": s.bracket(F, _H)}


@claim("s32-mu-eigen-times-zero", kind="id", sizes=admissible(n_max=3),
       statement="0 R(mu) = 0, mu = tr(Dn A (I - S))/2")
def mu_eigen_zero(s):
    """R(mu) exists at no point of any stated size (mu = a_1 there)."""
    mu = (s.tr(_Dn(s) @ s.A) - s.tr(_Dn(s) @ s.A @ _S(s))) / 2
    R = s.resolvent(mu)
    return {"r": R * 0, "x": s.X.T @ s.X - s.Ir}
