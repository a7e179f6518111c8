# ruff: noqa: F401
"""s89h3 c3: traces of sums inside derivatives, Hamiltonians, complex, killing, Rank.
M = PᵀAP (r×r), N = XᵀAX, flow = Dirac flow of the Neumann H = ½tr PᵀP + ½tr XᵀAX.
 h3-d-cube (TRUE): d tr(M³) = 3 tr(M² Ṁ) (chain rule + cyclicity).
 h3-d-cube-twin (FALSE): d tr(M³) = 2 tr(M² Ṁ)  (tr(M²Ṁ) ≠ 0 generically).
 h3-d-rect (TRUE): d tr(X Pᵀ A X Pᵀ) = tr(Ẋ Pᵀ A X Pᵀ + X Ṗᵀ A X Pᵀ + X Pᵀ A Ẋ Pᵀ + X Pᵀ A X Ṗᵀ), product rule.
 h3-d-rect-twin (FALSE): the same with the last term dropped.
 h3-ham-words (TRUE): for H2 = ½tr((PᵀP + XᵀAX)(PᵀP - XᵀAX)) + ½tr PᵀP, d H2 along its own Dirac flow = 0 (energy).
 h3-ham-words-twin (FALSE): d H2 along the Neumann flow = 0 (H2 is not a Neumann integral... checked by numpy below? no:
   by modular/rational and a numpy finite difference in truth.py).
 h3-conj (TRUE): tr(conj(Z)ᵀ... ) realified: tr(conj(W) W' - W' conj(W)) = 0, W = Zc Zcᵀ (2n×2n) — cyclicity.
 h3-conj-twin (FALSE): tr(conj(W) W W' - W conj(W) W') = 0 (conj(W) and W do not commute).
 h3-killing (TRUE): <Φ, Φ> + ½ tr(ΦΦ) = 0.
 h3-rank (dim, TRUE): the 1×1 matrix of tr(XᵀAX XᵀAX - XᵀAX XᵀAX) has rank 0 ... (expressed as Rank of c·I_r with c that cancels).
"""
from stiefelsym import admissible, claim, Rank

SZ = [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)]


def Hn(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def M(t):
    return t.P.T @ t.A @ t.P


@claim("h3-d-cube", kind="id", sizes=SZ)
def dcube(s):
    fl = s.dirac_flow(Hn)
    Md = s.d(M, fl)
    m = M(s)
    return {"r": s.d(lambda t: t.tr(M(t) @ M(t) @ M(t)), fl) - 3 * s.tr(m @ m @ Md)}


@claim("h3-d-cube-twin", kind="id", sizes=SZ)
def dcubet(s):
    fl = s.dirac_flow(Hn)
    Md = s.d(M, fl)
    m = M(s)
    return {"r": s.d(lambda t: t.tr(M(t) @ M(t) @ M(t)), fl) - 2 * s.tr(m @ m @ Md)}


def F(t):
    return t.tr(t.X @ t.P.T @ t.A @ t.X @ t.P.T)


@claim("h3-d-rect", kind="id", sizes=SZ)
def drect(s):
    fl = s.dirac_flow(Hn)
    Xd, Pd = fl["X"], fl["P"]
    X, P, A = s.X, s.P, s.A
    rhs = s.tr(Xd @ P.T @ A @ X @ P.T + X @ Pd.T @ A @ X @ P.T + X @ P.T @ A @ Xd @ P.T + X @ P.T @ A @ X @ Pd.T)
    return {"r": s.d(F, fl) - rhs}


@claim("h3-d-rect-twin", kind="id", sizes=SZ)
def drectt(s):
    fl = s.dirac_flow(Hn)
    Xd, Pd = fl["X"], fl["P"]
    X, P, A = s.X, s.P, s.A
    rhs = s.tr(Xd @ P.T @ A @ X @ P.T + X @ Pd.T @ A @ X @ P.T + X @ P.T @ A @ Xd @ P.T)
    return {"r": s.d(F, fl) - rhs}


def H2(t):
    a = t.P.T @ t.P
    b = t.X.T @ t.A @ t.X
    return t.tr((a + b) @ (a - b)) / 2 + t.tr(t.P.T @ t.P) / 2


@claim("h3-ham-words", kind="id", sizes=SZ)
def hamw(s):
    return {"r": s.d(H2, s.dirac_flow(H2))}


@claim("h3-ham-words-twin", kind="id", sizes=SZ)
def hamwt(s):
    return {"r": s.d(H2, s.dirac_flow(Hn))}


@claim("h3-conj", kind="id", sizes=SZ)
def cj(s):
    W = s.Zc @ s.Zc.T
    Wd = s.Zc_dot @ s.Zc.T
    return {"r": s.tr(s.conj(W) @ Wd - Wd @ s.conj(W))}


@claim("h3-conj-twin", kind="id", sizes=SZ)
def cjt(s):
    W = s.Zc @ s.Zc.T
    Wd = s.Zc_dot @ s.Zc.T
    return {"r": s.tr(s.conj(W) @ W @ Wd - W @ s.conj(W) @ Wd)}


@claim("h3-killing", kind="id", sizes=SZ)
def kil(s):
    return {"r": s.killing(s.Phi, s.Phi) + s.tr(s.Phi @ s.Phi) / 2}


@claim("h3-rank", kind="dim", sizes=SZ)
def rk(s):
    N = s.X.T @ s.A @ s.X
    G = s.generic("G", "r", "r")
    c = s.tr(N @ G @ N - G @ N @ N)
    return {"rank": Rank(c * s.Ir, 0, generic=True)}


@claim("h3-rank-twin", kind="dim", sizes=SZ)
def rkt(s):
    N = s.X.T @ s.A @ s.X
    G = s.generic("G", "r", "r")
    c = s.tr(N @ G @ N - G @ G @ N)
    return {"rank": Rank(c * s.Ir, 0, generic=True)}
