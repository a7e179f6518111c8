"""The dimension-free method's own derivatives (FreeScene.d, dual letters) against hand formulas, with a false
twin of each (one factor or sign changed).  TRUE claims end in -true, FALSE ones in -false."""
from stiefelsym import admissible, claim, elementary

SZ = admissible(n_max=3)


def mu_of(t):
    return t.tr(t.X.T @ t.A @ t.X)


def _moving_resolvent(s, k):
    V = s.fresh("n", "r")
    R = s.resolvent(mu_of(s))
    mud = s.tr(V.T @ s.A @ s.X) * 2
    got = s.d(lambda t: t.resolvent(mu_of(t)), {"X": V})
    return {"w": got + R @ R * mud * k}


@claim("s75-fd-resolvent-true", kind="id", sizes=SZ)
def fd_res_true(s):
    """d R(μ) = −μ̇ R², μ = tr XᵀAX: TRUE."""
    return _moving_resolvent(s, 1)


@claim("s75-fd-resolvent-false", kind="id", sizes=SZ)
def fd_res_false(s):
    """d R(μ) = −2μ̇ R²: FALSE."""
    return _moving_resolvent(s, 2)


def _second(s, k):
    V = s.fresh("n", "r")
    F = lambda t: t.tr(t.X.T @ t.X @ t.X.T @ t.X)
    got = s.d(lambda t: t.d(F, {"X": V}), {"X": V})
    S = V.T @ s.X + s.X.T @ V
    return {"w": got - (s.tr(S @ S) * 2 + s.tr(s.X.T @ s.X @ V.T @ V) * k)}


@claim("s75-fd-second-true", kind="id", sizes=SZ)
def fd_second_true(s):
    """d² tr((XᵀX)²) = 2 tr(S²) + 4 tr(XᵀX VᵀV): TRUE (ambient, V any direction)."""
    return _second(s, 4)


@claim("s75-fd-second-false", kind="id", sizes=SZ)
def fd_second_false(s):
    """... with 2 tr(XᵀX VᵀV): FALSE (on T*V XᵀX = I, so the term is 2 tr VᵀV ≠ 0)."""
    return _second(s, 2)


def _quot(s, k):
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    f = s.tr(s.X.T @ s.A @ s.P)
    g = s.tr(s.P.T @ s.P) + 1
    fd = s.tr(V.T @ s.A @ s.P) + s.tr(s.X.T @ s.A @ W)
    gd = s.tr(W.T @ s.P) * 2
    got = s.d(lambda t: t.tr(t.X.T @ t.A @ t.P) ** 3 / (t.tr(t.P.T @ t.P) + 1), {"X": V, "P": W})
    return {"w": got - (f * f * fd * g * 3 - f ** 3 * gd * k) / (g * g)}


@claim("s75-fd-quotient-true", kind="id", sizes=SZ)
def fd_quot_true(s):
    """d(f³/g) by the quotient rule: TRUE."""
    return _quot(s, 1)


@claim("s75-fd-quotient-false", kind="id", sizes=SZ)
def fd_quot_false(s):
    """... with −f³ġ/2·... (a factor 2 on ġ): FALSE."""
    return _quot(s, 2)


def _e3(s, k):
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    N = s.P.T @ s.A @ s.P
    Nd = W.T @ s.A @ s.P + s.P.T @ s.A @ W
    e = elementary(s, N, 2)
    got = s.d(lambda t: elementary(t, t.P.T @ t.A @ t.P, 3)[3], {"X": V, "P": W})
    # d e3 = tr(adj-like): e2 tr Ṅ − e1 tr(N Ṅ) + tr(N² Ṅ)
    return {"w": got - (e[2] * s.tr(Nd) - e[1] * s.tr(N @ Nd) + s.tr(N @ N @ Nd) * k)}


@claim("s75-fd-e3-true", kind="id", sizes=SZ)
def fd_e3_true(s):
    """d e₃(N) = e₂ tr Ṅ − e₁ tr(NṄ) + tr(N²Ṅ), N = PᵀAP: TRUE."""
    return _e3(s, 1)


@claim("s75-fd-e3-false", kind="id", sizes=SZ)
def fd_e3_false(s):
    """... with 2 tr(N²Ṅ): FALSE for r >= 1 (N generic symmetric r x r... 0 at r = 1? no: tr(N²Ṅ) ≠ 0)."""
    return _e3(s, 2)


def _energy(s, k):
    H = lambda t: t.tr(t.P.T @ t.resolvent(mu_of(t)) @ t.P) + mu_of(t) ** 2
    flow = s.dirac_flow(H)
    return {"w": s.d(H, flow) * 1 if k == 1 else s.d(lambda t: t.tr(t.P.T @ t.resolvent(mu_of(t)) @ t.P), flow)}


@claim("s75-fd-energy-true", kind="id", sizes=SZ)
def fd_energy_true(s):
    """H conserved along its own Dirac flow: TRUE."""
    return _energy(s, 1)


@claim("s75-fd-energy-false", kind="id", sizes=SZ)
def fd_energy_false(s):
    """its first term alone conserved: FALSE."""
    return _energy(s, 2)
