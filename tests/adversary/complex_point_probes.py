"""The complex point Zc (realified Z = U + iV of W(n, r), Z*Z = I), conj, realify, and derivatives along a
flow that moves Zc, probed for every method.  The true claims pass under every fixed-size method and
the false ones fail; the dimension-free algebra proves the true ones it can state and no false one.

* adv-cz-d-true (true): d tr(Zcᵀ Ar Zc) along Zc' = Zc_dot is 2 tr(Zcᵀ Ar Zc_dot) (Ar = realify(A, 0)).
  The dimension-free algebra moves X, P, Y, Q only: a flow that moves Zc is left to the fixed-size
  methods (undecided).  It used to answer `error` (a KeyError, as for a key no scene knows) on this true
  claim, which the mutation analysis counts as a refutation.
* adv-cz-d-bad-key (false, refused everywhere): a flow that moves Φ, which no scene moves: error.
"""
from stiefelsym import admissible, claim

ALL = admissible(n_max=4, n_min=2)

def I2r(s):
    return s.realify(s.Ir, 0 * s.Ir)


@claim("adv-cz-ZtconjZ", kind="id", sizes=ALL)
def a(s):
    """Zc^T conj(Zc) = I (false)."""
    return {"v": s.Zc.T @ s.conj(s.Zc) - I2r(s)}


@claim("adv-cz-conjZtconjZ-true", kind="id", sizes=ALL)
def b(s):
    """conj(Zc)^T conj(Zc) = I (true)."""
    return {"v": s.conj(s.Zc).T @ s.conj(s.Zc) - I2r(s)}


@claim("adv-cz-ZZtZ-true", kind="id", sizes=ALL)
def c(s):
    return {"v": s.Zc @ s.Zc.T @ s.Zc - s.Zc}


@claim("adv-cz-ZZt-false", kind="id", sizes=ALL)
def d(s):
    """Zc Zc^T = I (false for n > r; r = n true)"""
    return {"v": s.Zc @ s.Zc.T - s.realify(s.In, 0 * s.In)}


@claim("adv-cz-conj-product-true", kind="id", sizes=ALL)
def e(s):
    return {"v": s.conj(s.Zc @ s.Zc.T) - s.conj(s.Zc) @ s.conj(s.Zc).T}


@claim("adv-cz-conj-product-false", kind="id", sizes=ALL)
def f(s):
    return {"v": s.conj(s.Zc @ s.Zc.T) - s.Zc @ s.Zc.T}


@claim("adv-cz-conj-realify-false", kind="id", sizes=ALL)
def g(s):
    return {"v": s.conj(s.realify(s.X, s.P)) - s.realify(s.X, s.P)}


@claim("adv-cz-conj-realify-true", kind="id", sizes=ALL)
def h(s):
    return {"v": s.conj(s.realify(s.X, s.P)) - s.realify(s.X, -s.P)}


@claim("adv-cz-A-trace-false", kind="id", sizes=ALL)
def i(s):
    """tr(Zc^T realify(A,0) Zc) = tr(conj(Zc)^T realify(0,A) Zc) (false)"""
    Ar, Ai = s.realify(s.A, 0 * s.A), s.realify(0 * s.A, s.A)
    return {"v": s.tr(s.Zc.T @ Ar @ s.Zc) - s.tr(s.conj(s.Zc).T @ Ai @ s.Zc)}


@claim("adv-cz-imag-A-true", kind="id", sizes=ALL)
def j(s):
    """tr(Zc^T realify(0,A) Zc) = 0 (true: Z* (iA) Z has imaginary-part trace... realified trace of i*Hermitian is 0)"""
    Ai = s.realify(0 * s.A, s.A)
    return {"v": s.tr(s.Zc.T @ Ai @ s.Zc)}


@claim("adv-cz-tangent-conj-false", kind="id", sizes=ALL)
def k(s):
    """conj(Zc)^T Zc_dot + Zc_dot^T conj(Zc) = 0 (false)"""
    return {"v": s.conj(s.Zc).T @ s.Zc_dot + s.Zc_dot.T @ s.conj(s.Zc)}


@claim("adv-cz-d-true", kind="id", sizes=ALL)
def d_true(s):
    """d tr(Zc^T Ar Zc) along Zc' = Zc_dot is 2 tr(Zc^T Ar Zc_dot) (true)"""
    Ar = s.realify(s.A, 0 * s.A)
    return {"v": s.d(lambda u: u.tr(u.Zc.T @ Ar @ u.Zc), {"Zc": s.Zc_dot}) - 2 * s.tr(s.Zc.T @ Ar @ s.Zc_dot)}


@claim("adv-cz-d-conj-false", kind="id", sizes=ALL)
def m(s):
    """d tr(conj(Zc)^T Ai Zc) along Zc' = Zc_dot is 0 (false)"""
    Ai = s.realify(0 * s.A, s.A)
    return {"v": s.d(lambda u: u.tr(u.conj(u.Zc).T @ Ai @ u.Zc), {"Zc": s.Zc_dot})}


@claim("adv-cz-d-bad-key", kind="id", sizes=ALL)
def bad_key(s):
    """d tr(X^T X) along a flow that moves Phi is 0 (refused: no scene moves Phi)."""
    return {"v": s.d(lambda u: u.tr(u.X.T @ u.X), {"Phi": s.Phi})}
