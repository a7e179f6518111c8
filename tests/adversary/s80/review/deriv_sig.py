"""The shape-hint hold through systems.derivative (like={"F": "point"}): a stateful F handed to two derivative
calls whose points have another SIGNATURE (keys in another order; an extra key whose tangent is 0) is never
compared.  F(t, z) = c·tr(XᵀKX), X = z["X"], c = 1 at the first call and 2 at the second.
Truth (by hand): d/dε F(X + εV) = c·tr(Vᵀ(K + Kᵀ)X); a key of the point whose tangent is not given is fixed
(its tangent is 0), so adding P to the point does not change the derivative.  For ONE F, D1 = D2; the claim
says D1 = tr(Vᵀ(K + Kᵀ)X) and D2 = 2 tr(Vᵀ(K + Kᵀ)X), which differ (generic K, V, X).
  s80r-deriv-keyorder-contradiction: points {X, P} then {P, X}                               FALSE
  s80r-deriv-extrakey-contradiction: points {X} then {X, P}                                  FALSE
  s80r-deriv-control-true:           two F objects (c = 1, c = 2), points {X} then {X, P}      TRUE
  s80r-deriv-honest-false:           one stateless F (c = 1): the same two statements            FALSE (refuted)
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import derivative

SIZES = admissible(n_min=3, n_max=3)


def _want(s, K, V, c):
    return s.tr(V.T @ (K + K.T) @ s.X) * c


def _F(mode, K):
    def F(t, z):
        return t.tr(z["X"].T @ K @ z["X"]) * mode[0]
    return F


@claim("s80r-deriv-keyorder-contradiction", kind="id", sizes=SIZES)
def keyorder(s):
    K, V = s.generic("K", "n", "n"), s.generic("V", "n", "r")
    mode = [1]
    F = _F(mode, K)
    d1 = derivative(s, F, {"X": s.X, "P": s.P}, {"X": V})
    mode[0] = 2
    d2 = derivative(s, F, {"P": s.P, "X": s.X}, {"X": V})
    return {"D1": d1 - _want(s, K, V, 1), "D2": d2 - _want(s, K, V, 2)}


@claim("s80r-deriv-extrakey-contradiction", kind="id", sizes=SIZES)
def extrakey(s):
    K, V = s.generic("K", "n", "n"), s.generic("V", "n", "r")
    mode = [1]
    F = _F(mode, K)
    d1 = derivative(s, F, {"X": s.X}, {"X": V})
    mode[0] = 2
    d2 = derivative(s, F, {"X": s.X, "P": s.P}, {"X": V})
    return {"D1": d1 - _want(s, K, V, 1), "D2": d2 - _want(s, K, V, 2)}


@claim("s80r-deriv-control-true", kind="id", sizes=SIZES)
def control(s):
    K, V = s.generic("K", "n", "n"), s.generic("V", "n", "r")
    d1 = derivative(s, _F([1], K), {"X": s.X}, {"X": V})
    d2 = derivative(s, _F([2], K), {"X": s.X, "P": s.P}, {"X": V})
    return {"D1": d1 - _want(s, K, V, 1), "D2": d2 - _want(s, K, V, 2)}


@claim("s80r-deriv-honest-false", kind="id", sizes=SIZES)
def honest(s):
    K, V = s.generic("K", "n", "n"), s.generic("V", "n", "r")
    F = _F([1], K)
    d1 = derivative(s, F, {"X": s.X}, {"X": V})
    d2 = derivative(s, F, {"X": s.X, "P": s.P}, {"X": V})
    return {"D1": d1 - _want(s, K, V, 1), "D2": d2 - _want(s, K, V, 2)}
