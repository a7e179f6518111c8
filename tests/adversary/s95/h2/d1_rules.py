"""Derivative rules checked against derivatives written by hand (true claims) and their false twins."""
from fractions import Fraction

from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def G(s):
    return s.generic("V", "n", "r"), s.generic("W", "n", "r")


def _pow(s, M, k):
    out = M
    for _ in range(k - 1):
        out = out @ M
    return out


@claim("h2d-matpow", kind="id", sizes=SZ)
def matpow(s):
    """d (XX^T)^2 along V, by hand."""
    V, W = G(s)
    X = s.X
    S = X @ X.T
    dS = V @ X.T + X @ V.T
    return {"r": s.d(lambda t: (t.X @ t.X.T) ** 2, {"X": V}) - (dS @ S + S @ dS)}


@claim("h2d-matpow-false", kind="id", sizes=SZ)
def matpow_false(s):
    """False: d (XX^T)^2 = 2 (XX^T) d(XX^T)."""
    V, W = G(s)
    X = s.X
    S = X @ X.T
    dS = V @ X.T + X @ V.T
    return {"r": s.d(lambda t: (t.X @ t.X.T) ** 2, {"X": V}) - 2 * S @ dS}


@claim("h2d-inv", kind="id", sizes=SZ)
def inv_rule(s):
    """d (I + X^T X + P^T P)^{-1} along (V, W), by hand."""
    V, W = G(s)
    M = s.Ir + s.X.T @ s.X + s.P.T @ s.P
    dM = V.T @ s.X + s.X.T @ V + W.T @ s.P + s.P.T @ W
    Mi = M.inv()
    return {"r": s.d(lambda t: (t.Ir + t.X.T @ t.X + t.P.T @ t.P).inv(), {"X": V, "P": W}) + Mi @ dM @ Mi}


@claim("h2d-scalar-div", kind="id", sizes=SZ)
def scalar_div(s):
    """d (tr P^T P)^{-2} X / tr(X^T A X) along (V, W), by hand."""
    V, W = G(s)
    c = s.tr(s.P.T @ s.P)
    e = s.tr(s.X.T @ s.A @ s.X)
    dc = 2 * s.tr(W.T @ s.P)
    de = 2 * s.tr(V.T @ s.A @ s.X)
    f = lambda t: t.X * (t.tr(t.P.T @ t.P) ** -2) / t.tr(t.X.T @ t.A @ t.X)  # noqa: E731
    man = V / (c ** 2 * e) + s.X * (-2 * dc / (c ** 3 * e) - de / (c ** 2 * e ** 2))
    return {"r": s.d(f, {"X": V, "P": W}) - man}


@claim("h2d-phi-psi", kind="id", sizes=SZ)
def phi_psi(s):
    """d (Phi X - X Psi) along (V, W), by hand."""
    V, W = G(s)
    X, P = s.X, s.P
    Phi, Psi = s.Phi, s.Psi
    dPhi = W @ X.T + P @ V.T - V @ P.T - X @ W.T
    dPsi = V.T @ P + X.T @ W - W.T @ X - P.T @ V
    man = dPhi @ X + Phi @ V - V @ Psi - X @ dPsi
    return {"r": s.d(lambda t: t.Phi @ t.X - t.X @ t.Psi, {"X": V, "P": W}) - man}


@claim("h2d-killing-block", kind="id", sizes=SZ)
def killing_block(s):
    """d <Phi, [[X^T X, X^T P],[P^T X, P^T P]]-ish> along (V, W), by hand, through a block."""
    from stiefelsym import block
    V, W = G(s)

    def f(t):
        B = block([[t.X.T @ t.P, t.P.T @ t.P], [t.X.T @ t.X, t.P.T @ t.X]])
        return t.tr(B @ B)
    X, P = s.X, s.P
    B = block([[X.T @ P, P.T @ P], [X.T @ X, P.T @ X]])
    dB = block([[V.T @ P + X.T @ W, W.T @ P + P.T @ W], [V.T @ X + X.T @ V, W.T @ X + P.T @ V]])
    return {"r": s.d(f, {"X": V, "P": W}) - 2 * s.tr(B @ dB)}


@claim("h2d-resolvent-lam", kind="id", sizes=SZ)
def resolvent_lam(s):
    """d X^T R(lam) X along V with R = (lam I - A)^{-1} constant."""
    V, W = G(s)
    R = s.resolvent(s.lam)
    return {"r": s.d(lambda t: t.X.T @ t.resolvent(t.lam) @ t.X, {"X": V}) - (V.T @ R @ s.X + s.X.T @ R @ V)}


@claim("h2d-resolvent-moving", kind="id", sizes=SZ)
def resolvent_moving(s):
    """d R(tr X^T X) at moving mu along V: -R^2 d mu."""
    V, W = G(s)
    mu = s.tr(s.X.T @ s.X)
    R = s.resolvent(mu)
    dmu = 2 * s.tr(V.T @ s.X)
    return {"r": s.d(lambda t: t.resolvent(t.tr(t.X.T @ t.X)), {"X": V}) + R @ R * dmu}


@claim("h2d-nested", kind="id", sizes=SZ)
def nested(s):
    """Second derivative of tr (X^T A X)^2 along V, V: by hand."""
    V, W = G(s)
    X, A = s.X, s.A
    M = X.T @ A @ X
    dM = V.T @ A @ X + X.T @ A @ V
    ddM = 2 * V.T @ A @ V
    man = 2 * s.tr(dM @ dM) + 2 * s.tr(M @ ddM)
    inner = lambda t: t.d(lambda u: u.tr((u.X.T @ u.A @ u.X) @ (u.X.T @ u.A @ u.X)), {"X": V})  # noqa: E731
    return {"r": s.d(inner, {"X": V}) - man}


@claim("h2d-nested-closure", kind="id", sizes=SZ)
def nested_closure(s):
    """d of a function closing over the outer scene's X: only the inner X moves."""
    V, W = G(s)
    X0 = s.X
    f = lambda t: t.tr(X0.T @ t.A @ t.X)  # noqa: E731
    return {"r": s.d(f, {"X": V}) - s.tr(X0.T @ s.A @ V)}


@claim("h2d-frac-pow", kind="id", sizes=SZ)
def frac_pow(s):
    """d c^3 with c = tr X^T A X / 2."""
    V, W = G(s)
    c = s.tr(s.X.T @ s.A @ s.X) * Fraction(1, 2)
    dc = s.tr(V.T @ s.A @ s.X)
    return {"r": s.d(lambda t: (t.tr(t.X.T @ t.A @ t.X) * Fraction(1, 2)) ** 3, {"X": V}) - 3 * c ** 2 * dc}


@claim("h2d-entry-T", kind="id", sizes=admissible(n_min=2, r_min=2, n_max=3))
def entry_T(s):
    """d (X^T P)^T[0, 1] = (dX^T P + X^T dP)[1, 0]."""
    V, W = G(s)
    return {"r": s.d(lambda t: (t.X.T @ t.P).T[0, 1], {"X": V, "P": W}) - (V.T @ s.P + s.X.T @ W)[1, 0]}


@claim("h2d-entry-T-false", kind="id", sizes=admissible(n_min=2, r_min=2, n_max=3))
def entry_T_false(s):
    """False: d (X^T P)^T[0, 1] = (dX^T P + X^T dP)[0, 1]."""
    V, W = G(s)
    return {"r": s.d(lambda t: (t.X.T @ t.P).T[0, 1], {"X": V, "P": W}) - (V.T @ s.P + s.X.T @ W)[0, 1]}


@claim("h2d-grad-inv", kind="id", sizes=SZ)
def grad_inv(s):
    """gradient of tr (I + X^T X)^{-1} in X: -2 X M^{-2} (M symmetric)."""
    M = s.Ir + s.X.T @ s.X
    Mi = M.inv()
    HX, HP = s.gradient(lambda t: t.tr((t.Ir + t.X.T @ t.X).inv()))
    return {"X": HX + 2 * s.X @ Mi @ Mi, "P": HP}


@claim("h2d-grad-nonsym", kind="id", sizes=SZ)
def grad_nonsym(s):
    """gradient of tr((X^T A P)^2 (P^T P)^{-1}) in X and P, by hand (non-symmetric pieces)."""
    X, P, A = s.X, s.P, s.A
    B = X.T @ A @ P
    C = (P.T @ P).inv()
    # f = tr(B B C); df = tr(dB B C + B dB C) ; dB = dX^T A P + X^T A dP ; dC = -C (dP^T P + P^T dP) C
    # grad_X: tr(dX^T A P (B C + C B)) => A P (BC + CB)^T
    # grad_P from dB: tr(X^T A dP (BC+CB)) => A^T X (BC+CB)^T ; from dC: tr(B B dC) = -tr(C B B C (dP^T P + P^T dP))
    K = C @ B @ B @ C
    gX = A @ P @ (B @ C + C @ B)
    gP = A.T @ X @ (B @ C + C @ B).T - P @ (K + K.T)
    HX, HP = s.gradient(lambda t: t.tr((t.X.T @ t.A @ t.P) @ (t.X.T @ t.A @ t.P) @ (t.P.T @ t.P).inv()))
    return {"X": HX - gX, "P": HP - gP}
