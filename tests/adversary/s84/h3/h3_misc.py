"""h3 (stop 84): other doors to a size in a denominator or an empty check (sizes 1 <= r <= n <= 3).

h3-m-q-dim          s.q(1, s.n - s.r) * (tr I_n - tr I_r) - 1: a rational constant with a size difference as its
                    denominator: UNDEF at r = n (an `error` there at fixed sizes, or refused when traced).
h3-m-q-dim-ok       s.q(1, s.n + s.r) * (tr I_n + tr I_r) - 1: TRUE (or refused: s.q wants ints).
h3-m-zeros-r1       {"z": s.zeros(s.r - 1, s.r, ("r-1", "r"))}: empty at r = 1 -> `error` expected (or refused).
h3-m-scalarmat      s.scalar_matrix(1/(n - r + 1), s.n) @ X * (n - r + 1) - X: TRUE (free refusal fine).
h3-m-scalarmat-nr   s.scalar_matrix(1/(n*n - r*r) ... ) : X/(n^2-r^2)*(n^2-r^2) - X via scalar_matrix: UNDEF at r = n.
h3-m-flow-div       d/dt along the Dirac flow of H = tr(P^T P)/(2(n + r)) of tr(X^T X): TRUE (0: X^T X = I on T*V).
h3-m-flow-div-nr    the same with H = tr(P^T P)/(n - r): H is UNDEF at r = n -> no `proved`.
h3-m-grad-div-nr    the gradient of H = tr(X^T A X)/(n*n - r*r) minus itself... : {"x": HX - HX}: UNDEF at r = n.
h3-m-res-div        (lam + n) * R(lam + n) @ ... : resolvent at lam + n, R(mu)(mu I - A) - I with mu = lam + n: TRUE.
h3-m-res-two        R(lam + n) - R(lam + r) - (r - n) R(lam + n) R(lam + r): TRUE polynomial identity
                    (resolvent identity, valid also at r = n, where both sides are 0).  A refusal is an F.
h3-m-res-two-div    (R(lam + n) - R(lam + r)) / (r - n) - R(lam+n) R(lam+r) : UNDEF at r = n (the claim divides by r - n).
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _n(s):
    return s.tr(s.In)


def _r(s):
    return s.tr(s.Ir)


@claim("h3-m-q-dim", kind="id", sizes=SZ)
def m1(s):
    return {"x": s.q(1, s.n - s.r) * (_n(s) - _r(s)) - 1}


@claim("h3-m-q-dim-ok", kind="id", sizes=SZ)
def m2(s):
    return {"x": s.q(1, s.n + s.r) * (_n(s) + _r(s)) - 1}


@claim("h3-m-zeros-r1", kind="id", sizes=SZ)
def m3(s):
    return {"z": s.zeros(s.r - 1, s.r, ("r-1", "r"))}


@claim("h3-m-scalarmat", kind="id", sizes=SZ)
def m4(s):
    k = _n(s) - _r(s) + 1
    return {"x": s.scalar_matrix(1 / k, s.n) @ s.X * k - s.X}


@claim("h3-m-scalarmat-nr", kind="id", sizes=SZ)
def m5(s):
    k = _n(s) * _n(s) - _r(s) * _r(s)
    return {"x": s.scalar_matrix(1 / k, s.n) @ s.X * k - s.X}


@claim("h3-m-flow-div", kind="id", sizes=SZ)
def m6(s):
    def H(t):
        return t.tr(t.P.T @ t.P) / (2 * (t.tr(t.In) + t.tr(t.Ir)))
    return {"x": s.d(lambda t: t.tr(t.X.T @ t.X), s.dirac_flow(H))}


@claim("h3-m-flow-div-nr", kind="id", sizes=SZ)
def m7(s):
    def H(t):
        return t.tr(t.P.T @ t.P) / (t.tr(t.In) - t.tr(t.Ir))
    return {"x": s.d(lambda t: t.tr(t.X.T @ t.X), s.dirac_flow(H))}


@claim("h3-m-grad-div-nr", kind="id", sizes=SZ)
def m8(s):
    def H(t):
        n, r = t.tr(t.In), t.tr(t.Ir)
        return t.tr(t.X.T @ t.A @ t.X) / (n * n - r * r)
    HX, HP = s.gradient(H)
    return {"x": HX - HX}


@claim("h3-m-res-div", kind="id", sizes=SZ)
def m9(s):
    mu = s.lam + _n(s)
    R = s.resolvent(mu)
    return {"x": R @ (s.scalar_matrix(mu, s.n) - s.A) - s.In}


@claim("h3-m-res-two", kind="id", sizes=SZ)
def m10(s):
    n, r = _n(s), _r(s)
    R1, R2 = s.resolvent(s.lam + n), s.resolvent(s.lam + r)
    return {"x": R1 - R2 - (r - n) * (R1 @ R2)}


@claim("h3-m-res-two-div", kind="id", sizes=SZ)
def m11(s):
    n, r = _n(s), _r(s)
    R1, R2 = s.resolvent(s.lam + n), s.resolvent(s.lam + r)
    return {"x": (R1 - R2) / (r - n) - R1 @ R2}
