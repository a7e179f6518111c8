"""Theorem 4.4: along the Manakov flow (dot_XP3*) the dual Lax matrix (MAN-LA2) does not satisfy
(MAN-LA) d L*/dt = [L*, A*] with A*_man(lambda) as printed in (LA-MAN3), whose blocks contain
(A + lambda I_n)^{-1}; it does with (A + lambda I_n) in their place."""
import sympy as sp

CHECK = "d𝓛*_man/dt − [𝓛*_man, 𝓐*_man]"


def residuals(W):
    X, P, A, lam = W["X"], W["P"], W["A"], W["lam"]
    n = A.shape[0]
    t = sp.Symbol("t")
    R = (lam * sp.eye(n) - A).inv()                       # R_lambda = (lambda I_n - A)^{-1}

    def L_star(X, P):                                     # (MAN-LA2)
        return sp.Matrix(sp.BlockMatrix([[-X.T * R * P, -X.T * R * X],
                                         [P.T * R * P, P.T * R * X]]))

    def A_star(S):                                        # (LA-MAN3), S in the place of (A + lambda I)^{-1}
        return sp.Matrix(sp.BlockMatrix([[X.T * S * P, X.T * S * X],
                                         [-P.T * S * P, -P.T * S * X]]))

    Phi = P * X.T - X * P.T                               # Phi = P X^T - X P^T
    Xdot = A * Phi * X + Phi * A * X                      # (dot_XP3*)
    Pdot = A * Phi * P + Phi * A * P
    dL = sp.diff(L_star(X + t * Xdot, P + t * Pdot), t).subs(t, 0)
    L = L_star(X, P)

    def lax(M):                                           # (MAN-LA): dL*/dt - [L*, A*]
        return dL - (L * M - M * L)

    printed = lax(A_star((A + lam * sp.eye(n)).inv()))   # (LA-MAN3) as printed
    corrected = lax(A_star(A + lam * sp.eye(n)))          # the correction: (A + lambda I_n)
    return {"printed": printed, "corrected": corrected}
