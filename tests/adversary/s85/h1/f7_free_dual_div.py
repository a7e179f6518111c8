"""Free method: divisions made inside a function the scene differentiates (tangent numbers: FreeField.reciprocal
hands a tangent number to its own division, not to the door for divisors).

V = {"X": s.X @ s.eta, "P": s.P @ s.eta} (a tangent vector; η generic skew r×r).
dd-nr        d/dε [X/(n − r)] along V − XΗ/(n − r)          0 where r < n; a division by 0 at r = n (exact: error)
dd-k         the same with k = 1 − 2r/(n + r) = (n − r)/(n + r)  -- the W1 form of stop 84
dd-nr-f      d/dε [X/(n − r)] along V − Xη                   FALSE at r < n, a division by 0 at r = n
dd-n4        d/dε [X/(n − 4)] along V − Xη/(n − 4)           a division by 0 at n = 4
dd-ok-t      d/dε [X/(n + r)] along V − Xη/(n + r)           TRUE at every size (control)
dd-tr-f      d/dε [X / tr(PᵀP)] along V − Xη/tr(PᵀP)         TRUE where P ≠ 0 (tr PᵀP is conserved along V); a
             division by a trace, refused outside a derivative -- is it refused inside?
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4)


def _V(s):
    return {"X": s.X @ s.eta, "P": s.P @ s.eta}


def _nr(t):
    return t.tr(t.In) - t.tr(t.Ir)


def _k(t):
    return 1 - 2 * t.tr(t.Ir) / (t.tr(t.In) + t.tr(t.Ir))


@claim("dd-nr", kind="id", sizes=SZ)
def dd_nr(s):
    return {"x": s.d(lambda t: t.X / _nr(t), _V(s)) - s.X @ s.eta / _nr(s)}


@claim("dd-nr-only-inside", kind="id", sizes=SZ)
def dd_nr_inside(s):
    # the only division is inside the function: d/dε[(n − r)·X/(n − r)] − Xη
    return {"x": s.d(lambda t: t.X * _nr(t) / _nr(t), _V(s)) - s.X @ s.eta}


@claim("dd-k-inside", kind="id", sizes=SZ)
def dd_k_inside(s):
    return {"x": s.d(lambda t: t.X * _k(t) / _k(t), _V(s)) - s.X @ s.eta}


@claim("dd-nr-f", kind="id", sizes=SZ)
def dd_nr_f(s):
    return {"x": s.d(lambda t: t.X / _nr(t), _V(s)) - s.X @ s.eta}


@claim("dd-ok-t", kind="id", sizes=SZ)
def dd_ok_t(s):
    N = lambda t: t.tr(t.In) + t.tr(t.Ir)   # noqa: E731
    return {"x": s.d(lambda t: t.X / N(t), _V(s)) - s.X @ s.eta / N(s)}


@claim("dd-tr-inside", kind="id", sizes=SZ)
def dd_tr_inside(s):
    w = lambda t: t.tr(t.P.T @ t.P)   # noqa: E731
    return {"x": s.d(lambda t: t.X * w(t) / w(t), _V(s)) - s.X @ s.eta}


@claim("dd-tr-inside-f", kind="id", sizes=SZ)
def dd_tr_inside_f(s):
    w = lambda t: t.tr(t.P.T @ t.P)   # noqa: E731
    return {"x": s.d(lambda t: t.X / w(t), _V(s))}
