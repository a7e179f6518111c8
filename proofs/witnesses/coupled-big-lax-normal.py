"""(so(n,n)) for the r-coupled Neumann system with the normal metric (kappa = 0): along its flow (C-eq)
(with Y Pi, the Hamiltonian flow of (C-neumann)) the printed L(nu), A(nu) = L_+(nu) do not satisfy
dL/dt = [L, A]; the correction: -nu^{-1} in front of the last term of L(nu), and dL/dt = [A(nu), L(nu)]."""
import sympy as sp

CHECK = "dL(ν)/dt − [L(ν), A(ν)]"


def residuals(W):
    X, P, Y, Q, A, nu = W["X"], W["P"], W["Y"], W["Q"], W["A"], W["nu"]
    n = A.shape[0]
    t = sp.Symbol("t")
    O = sp.zeros(n)
    S = (X.T * A * Y + Y.T * A * X) / 2
    Lam, Pi = S - P.T * P, S - Q.T * Q                         # (C-L)
    Xdot = P - X * P.T * X                                      # (C-eq), kappa = 0, with Y Pi
    Pdot = -A * Y + P * X.T * P + X * Lam
    Ydot = Q - Y * Q.T * Y
    Qdot = -A * X + Q * Y.T * Q + Y * Pi

    def big(X, P, Y, Q, sign):                                  # (so(n,n)): L(nu) and A(nu) = L_+(nu)
        J = sp.Matrix(sp.BlockMatrix([[O, A], [A, O]]))
        M = sp.Matrix(sp.BlockMatrix([[P * X.T - X * P.T, O], [O, Q * Y.T - Y * Q.T]]))
        K = sp.Matrix(sp.BlockMatrix([[O, X * Y.T], [Y * X.T, O]]))
        return J * nu + M + sign * K / nu, J * nu + M

    def dL(sign):
        return sp.diff(big(X + t * Xdot, P + t * Pdot, Y + t * Ydot, Q + t * Qdot, sign)[0], t).subs(t, 0)

    L, A_nu = big(X, P, Y, Q, 1)
    printed = dL(1) - (L * A_nu - A_nu * L)                     # as printed: +nu^{-1} K, dL/dt = [L, A]
    L, A_nu = big(X, P, Y, Q, -1)
    corrected = dL(-1) - (A_nu * L - L * A_nu)                  # the correction: -nu^{-1} K, dL/dt = [A, L]
    return {"printed": printed, "corrected": corrected}
