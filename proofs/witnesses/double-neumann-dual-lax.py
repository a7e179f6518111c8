"""Theorem 10.1: with (I_n - lambda A)^{-1} in the off-diagonal blocks of L(lambda), as printed in (LA3*D),
the double Neumann system (D-eq) does not imply dL/dt = [L, A]; it does with (lambda I_n - A)^{-1} there.
The point (X, Y, X', Y') of the double system: X^T Y = I_r, X'^T Y + X^T Y' = 0."""
import sympy as sp

CHECK = "d𝓛(λ)/dt − [𝓛(λ), 𝓐(λ)]"


def residuals(W):
    X, Y, Xd, Yd, A, lam = W["X"], W["Y"], W["Xdot"], W["Ydot"], W["A"], W["lam"]
    n, r = X.shape
    t = sp.Symbol("t")
    R = (lam * sp.eye(n) - A).inv()                         # (lambda I_n - A)^{-1}
    Lam = X.T * A * Y - Xd.T * Yd                           # (D-L)
    Xdd = -A * X + X * Lam.T                                # (D-eq)
    Ydd = -A * Y + Y * Lam

    def L_D(S, X, Y, Xd, Yd):                               # (LA3*D), S in the off-diagonal blocks
        return sp.Matrix(sp.BlockMatrix([[-X.T * R * Yd, -X.T * S * Y],
                                         [sp.eye(r) + Xd.T * S * Yd, Xd.T * R * Y]]))

    A_D = sp.Matrix(sp.BlockMatrix([[sp.zeros(r), sp.eye(r)],                   # (LA3*D): A(lambda)
                                    [Lam - lam * sp.eye(r), sp.zeros(r)]]))

    def lax(S):                                             # dL/dt - [L, A] along (D-eq)
        dL = sp.diff(L_D(S, X + t * Xd, Y + t * Yd, Xd + t * Xdd, Yd + t * Ydd), t).subs(t, 0)
        L = L_D(S, X, Y, Xd, Yd)
        return dL - (L * A_D - A_D * L)

    printed = lax((sp.eye(n) - lam * A).inv())             # (LA3*D) as printed: (I_n - lambda A)^{-1}
    corrected = lax(R)                                      # the correction: (lambda I_n - A)^{-1}
    return {"printed": printed, "corrected": corrected}
