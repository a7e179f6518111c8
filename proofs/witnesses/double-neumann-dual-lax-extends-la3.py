"""The sentence before Theorem 10.1: (LA3*D) is said to extend (LA3), but at X = Y, X' = Y' = P the printed
L(lambda) of (LA3*D), with (I_n - lambda A)^{-1} in its off-diagonal blocks, is not L*_neum(lambda) of
(LA3); with (lambda I_n - A)^{-1} there (the correction) it is."""
import sympy as sp

CHECK = "𝓛(λ) − 𝓛*_neum(λ)"


def residuals(W):
    X, P, A, lam = W["X"], W["P"], W["A"], W["lam"]
    n, r = X.shape
    R = (lam * sp.eye(n) - A).inv()                         # (lambda I_n - A)^{-1}
    Y, Xd, Yd = X, P, P                                     # the diagonal: X = Y, X' = Y' = P

    def L_D(S):                                             # (LA3*D), S in the off-diagonal blocks
        return sp.Matrix(sp.BlockMatrix([[-X.T * R * Yd, -X.T * S * Y],
                                         [sp.eye(r) + Xd.T * S * Yd, Xd.T * R * Y]]))

    L_neum = sp.Matrix(sp.BlockMatrix([[-X.T * R * P, -X.T * R * X],           # (LA3)
                                       [sp.eye(r) + P.T * R * P, P.T * R * X]]))
    printed = L_D((sp.eye(n) - lam * A).inv()) - L_neum    # (LA3*D) as printed: (I_n - lambda A)^{-1}
    corrected = L_D(R) - L_neum                             # the correction: (lambda I_n - A)^{-1}
    return {"printed": printed, "corrected": corrected}
