"""Derivatives on an enclosing scene along flows mixing levels, and at_point of inner values.
s.d(t ↦ ..., {"X": U, "P": W}) (ε₁), t.d(u ↦ ..., {"X": V, "P": Z}) (ε₂), inner derivative ε₃.
t.X = X + ε₁U, t.P = P + ε₁W, u.X = t.X + ε₂V, u.P = t.P + ε₂Z."""
from stiefelsym import admissible, claim
from stiefelsym.twisted import at_point

SZ = admissible(n_max=3)


def _vars(s):
    return s.fresh("n", "r"), s.fresh("n", "r"), s.fresh("n", "r"), s.fresh("n", "r")


def _nest(s, U, W, V, Z, body):
    return s.d(lambda t: t.d(lambda u: body(t, u), {"X": V, "P": Z}), {"X": U, "P": W})


# M1: t.d(k ↦ tr(k.Xᵀk.P), {"X": u.P, "P": t.X}) inside u: d3 = tr(u.Pᵀt.P) + tr(t.Xᵀt.X); d2 = tr(Zᵀt.P); d1 = tr(ZᵀW)
def _m1(s, U, W, V, Z):
    return _nest(s, U, W, V, Z, lambda t, u: t.d(lambda k: k.tr(k.X.T @ k.P), {"X": u.P, "P": t.X}))


@claim("r2-mix-xp-true", kind="id", sizes=SZ)
def m1_true(s):
    U, W, V, Z = _vars(s)
    return {"w": _m1(s, U, W, V, Z) - s.tr(Z.T @ W)}


@claim("r2-mix-xp-false", kind="id", sizes=SZ)
def m1_false(s):
    U, W, V, Z = _vars(s)
    return {"w": _m1(s, U, W, V, Z) - s.tr(Z.T @ W) * 2}


# M2: product: F = tr(k.Xᵀk.P)·tr(k.Xᵀk.X) along {"X": u.P, "P": t.X}:
# d3 = [tr(u.Pᵀt.P) + |t.X|²]·|t.X|² + tr(t.Xᵀt.P)·2tr(t.Xᵀu.P)
# d2 = tr(Zᵀt.P)|t.X|² + 2tr(t.Xᵀt.P)tr(t.XᵀZ)
# d1 = tr(ZᵀW)|X|² + tr(ZᵀP)·2tr(XᵀU) + 2[tr(UᵀP) + tr(XᵀW)]tr(XᵀZ) + 2tr(XᵀP)tr(UᵀZ)
def _m2(s, U, W, V, Z):
    return _nest(s, U, W, V, Z, lambda t, u: t.d(lambda k: k.tr(k.X.T @ k.P) * k.tr(k.X.T @ k.X),
                                                  {"X": u.P, "P": t.X}))


def _m2_truth(s, U, W, V, Z):
    X, P, tr = s.X, s.P, s.tr
    return (tr(Z.T @ W) * tr(X.T @ X) + tr(Z.T @ P) * tr(X.T @ U) * 2
            + (tr(U.T @ P) + tr(X.T @ W)) * tr(X.T @ Z) * 2 + tr(X.T @ P) * tr(U.T @ Z) * 2)


@claim("r2-mix-prod-true", kind="id", sizes=SZ)
def m2_true(s):
    U, W, V, Z = _vars(s)
    return {"w": _m2(s, U, W, V, Z) - _m2_truth(s, U, W, V, Z)}


@claim("r2-mix-prod-false", kind="id", sizes=SZ)
def m2_false(s):
    U, W, V, Z = _vars(s)
    return {"w": _m2(s, U, W, V, Z) - _m2_truth(s, U, W, Z, V)}


# M3: at_point(t, u.X, t.P).d(k ↦ tr(k.XᵀAk.X), {"X": t.P}) (flow: at_point's field is u's; t.P lifted):
# k.X = u.X + ε3 t.P: d3 = 2tr(u.XᵀA t.P); d2 = 2tr(VᵀA t.P); d1 = 2tr(VᵀAW)
def _m3(s, U, W, V, Z):
    return _nest(s, U, W, V, Z, lambda t, u: at_point(t, u.X, t.P).d(lambda k: k.tr(k.X.T @ k.A @ k.X),
                                                                     {"X": t.P}))


@claim("r2-atp-mixed-true", kind="id", sizes=SZ)
def m3_true(s):
    U, W, V, Z = _vars(s)
    return {"w": _m3(s, U, W, V, Z) - s.tr(V.T @ s.A @ W) * 2}


@claim("r2-atp-mixed-false", kind="id", sizes=SZ)
def m3_false(s):
    U, W, V, Z = _vars(s)
    return {"w": _m3(s, U, W, V, Z) - s.tr(U.T @ s.A @ W) * 2}


# M4: at_point(t, u.X, u.P).d(k ↦ |k.X|², canonical flow of H = ½|P|² + ½tr(XᵀAX) there) = 2tr(u.Xᵀu.P)
# d2 = 2tr(Vᵀt.P) + 2tr(t.XᵀZ); d1 = 2tr(VᵀW) + 2tr(UᵀZ)
def _H(k):
    return k.tr(k.P.T @ k.P) / 2 + k.tr(k.X.T @ k.A @ k.X) / 2


def _m4(s, U, W, V, Z):
    def body(t, u):
        k0 = at_point(t, u.X, u.P)
        return k0.d(lambda k: k.tr(k.X.T @ k.X), k0.canonical_flow(_H))
    return _nest(s, U, W, V, Z, body)


@claim("r2-atp-canon-true", kind="id", sizes=SZ)
def m4_true(s):
    U, W, V, Z = _vars(s)
    return {"w": _m4(s, U, W, V, Z) - (s.tr(V.T @ W) + s.tr(U.T @ Z)) * 2}


@claim("r2-atp-canon-false", kind="id", sizes=SZ)
def m4_false(s):
    U, W, V, Z = _vars(s)
    return {"w": _m4(s, U, W, V, Z) - (s.tr(V.T @ W) + s.tr(U.T @ W)) * 2}


# M5: the Dirac flow of H at at_point(t, u.X, u.P) is u's own (the same problem at the same point):
# d of tr(k.XᵀA k.P) along it, minus the same on u: 0 (TRUE); the false twin subtracts the canonical flow's
def _m5(s, U, W, V, Z, canon=False):
    def body(t, u):
        k0 = at_point(t, u.X, u.P)
        F = lambda k: k.tr(k.X.T @ k.A @ k.P) * k.tr(k.X.T @ k.X)  # noqa: E731
        other = u.canonical_flow(_H) if canon else u.dirac_flow(_H)
        return k0.d(F, k0.dirac_flow(_H)) - u.d(F, other)
    return _nest(s, U, W, V, Z, body)


@claim("r2-atp-dirac-true", kind="id", sizes=SZ)
def m5_true(s):
    U, W, V, Z = _vars(s)
    return {"w": _m5(s, U, W, V, Z)}


@claim("r2-atp-dirac-false", kind="id", sizes=[(2, 1), (3, 1), (3, 2)])
def m5_false(s):
    U, W, V, Z = _vars(s)
    return {"w": _m5(s, U, W, V, Z, canon=True)}
