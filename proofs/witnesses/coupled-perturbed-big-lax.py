"""(so(n,n)) for the perturbed Hamiltonian H_kappa = T_kappa + tr(X^T A Y) - 2 kappa tr(X^T P Y^T Q): along
its flow the printed L(nu), A(nu) = L_+(nu) do not satisfy dL/dt = [L, A]; the correction: -nu^{-1} in
front of the last term of L(nu), and dL/dt = [A(nu), L(nu)]."""
import sympy as sp

CHECK = "dL(ν)/dt − [L(ν), A(ν)]"


def residuals(W):
    X, P, Y, Q, A, nu, kappa = W["X"], W["P"], W["Y"], W["Q"], W["A"], W["nu"], W["kappa"]
    n = A.shape[0]
    t = sp.Symbol("t")
    O = sp.zeros(n)
    S = (X.T * A * Y + Y.T * A * X) / 2
    Lam, Pi = S - P.T * P, S - Q.T * Q                         # (C-L)
    Xdot = P - X * P.T * X                                      # (C-eq) at kappa = 0, with Y Pi
    Pdot = -A * Y + P * X.T * P + X * Lam
    Ydot = Q - Y * Q.T * Y
    Qdot = -A * X + Q * Y.T * Q + Y * Pi
    # H_kappa = H|_{kappa=0} - kappa tr(Sg^2), Sg = X^T P + Y^T Q: the flow of the last term is the right
    # diagonal action X' = X omega, P' = P omega, Y' = Y omega, Q' = Q omega with omega = 2 kappa Sg
    omega = 2 * kappa * (X.T * P + Y.T * Q)
    Xdot, Pdot, Ydot, Qdot = Xdot + X * omega, Pdot + P * omega, Ydot + Y * omega, Qdot + Q * omega

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
