"""The symmetric Clebsch-Perelomov-Bogoyavlenski body, (Euler) and (Poisson) on T*SO(n): the paper says
that with eta_so(r) = 0 the reduction gives the normal Neumann system (N0_XP2) on V_{n,r}; the right
condition is eta_so(n-r) = 0 (the correction).  Here n = 3 and r = 1 (k below): V_{3,1} = S^2."""
import sympy as sp

k = 1                                                  # the paper's r: H_CPB has the first k columns
CHECK = "dPᵣ/dt − Ṗᵣ by (4) §5 (r = 1)"


def residuals(W):
    X0, P0 = W["X"], W["P"]
    n = X0.shape[0]
    # A = diag(a_1, ..., a_n), kept symbolic when the point does not record it: for r = 1 the terms
    # in A cancel between (Euler) and (N0_XP2), and the residual is a number
    A = W["A"] if "A" in W else sp.diag(*sp.symbols(f"a1:{n + 1}"))
    t = sp.Symbol("t")
    D = sp.diag(*([1] * k + [0] * (n - k)))           # so(r) = span{E_i ^ E_j, i, j <= k}
    Ek = sp.eye(n)[:, :k]                              # X Ek = X_r = (e_1, ..., e_r)

    def residual(Z):
        """At the point of T*SO(n) where the block Z m Z of the body momentum m = X^T P vanishes."""
        P = P0 - X0 * (Z * (X0.T * P0) * Z)
        X = X0
        Omega = P * X.T - X * P.T                      # Omega = M = Phi
        v = X * D * X.T                                # v = e_1 (x) e_1 + ... + e_r (x) e_r
        Omegadot = v * A - A * v                       # (Euler): dOmega/dt = [v, A]
        Xdot = Omega * X                               # (Poisson): de_i/dt = Omega e_i

        def image(X, Omega):                           # (X_r, P_r), P_r = Omega X_r - 1/2 X_r X_r^T Omega X_r
            Xr = X * Ek
            return Xr, Omega * Xr - Xr * Xr.T * Omega * Xr / 2

        Xr, Pr = image(X, Omega)
        dPr = sp.diff(image(X + t * Xdot, Omega + t * Omegadot)[1], t).subs(t, 0)
        target = -A * Xr + Pr * Xr.T * Pr - Xr * Pr.T * Pr + Xr * Xr.T * A * Xr    # (N0_XP2) for dP/dt
        return dPr - target

    printed = residual(D)                              # eta_so(r) = 0, as printed
    corrected = residual(sp.eye(n) - D)                # the correction: eta_so(n-r) = 0
    return {"printed": printed, "corrected": corrected}
