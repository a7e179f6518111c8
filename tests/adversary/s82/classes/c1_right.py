"""Class 1 (chart choice): constants on R^r and the right-reduced charts (X = I at r = n; S11 = 0 below).

D = diag(1, −1, …) on R^r (s.mat, typed ("r", "r")), K = XᵀAX.
 rr-comm-false:  K D − D K = 0: FALSE (at X = I, r = n, K = A is diagonal and commutes with D; at X = h ∈ O(n) K =
                 hᵀAh does not).  At r < n: K = XᵀAX is a general symmetric r×r matrix: FALSE too.
 rr-comm-true:   (K D − D K)ᵀ + (K D − D K) = 0... (KD − DK)ᵀ = DK − KD: TRUE.
 rr-diag-false:  tr(D K D K) − tr(K K) = 0: FALSE (= −2 Σ_{i≠j, signs differ} K_ij²; 0 when K is diagonal).
 rr-sym-true:    tr(D K D K) − tr(K D K D) = 0: TRUE (cyclic).
 rr-ent-false:   K[0, 1] = 0 (an entry read of an r×r matrix): FALSE.
"""
from stiefelsym import claim

SZ = [(2, 2), (3, 3), (3, 2)]


def _D(s):
    r = int(s.r)
    return s.mat([[(1 if i == 0 else -1) if i == j else 0 for j in range(r)] for i in range(r)], ("r", "r"))


def _K(s):
    return s.X.T @ s.A @ s.X


@claim("rr-comm-false", kind="id", sizes=SZ)
def comm_false(s):
    K, D = _K(s), _D(s)
    return {"KD - DK": K @ D - D @ K}


@claim("rr-comm-true", kind="id", sizes=SZ)
def comm_true(s):
    K, D = _K(s), _D(s)
    C = K @ D - D @ K
    return {"C + Ct": C + C.T}


@claim("rr-diag-false", kind="id", sizes=SZ)
def diag_false(s):
    K, D = _K(s), _D(s)
    return {"tr": s.tr(D @ K @ D @ K) - s.tr(K @ K)}


@claim("rr-sym-true", kind="id", sizes=SZ)
def sym_true(s):
    K, D = _K(s), _D(s)
    return {"tr": s.tr(D @ K @ D @ K) - s.tr(K @ D @ K @ D)}


@claim("rr-ent-false", kind="id", sizes=SZ)
def ent_false(s):
    return {"K01": _K(s)[0, 1]}
