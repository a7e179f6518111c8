"""The paragraph after Proposition 9.1 (n = 3, r = 2, eta = Psi = epsilon E_1 ^ E_2): the Lorentz force of
the monopole is printed as F_Omega de_3/dt = +epsilon e_3 x de_3/dt; with F_Omega from (mag6) it is
F_Omega de_3/dt = -epsilon e_3 x de_3/dt (the correction)."""

CHECK = "F_Ω ė₃ − ε e₃ × ė₃"


def residuals(W):
    X, P = W["X"], W["P"]
    e1, e2 = X[:, 0], X[:, 1]
    e3 = e1.cross(e2)                                  # (3) of section 7: e_3 = e_1 x e_2
    Omega = P * X.T - X * P.T                          # Omega = Phi = P X^T - X P^T
    e3dot = Omega * e3                                 # (mag2): de_3/dt = Omega e_3
    F = Omega - (e3dot * e3.T - e3 * e3dot.T)          # (mag6): F_Omega = Omega - de_3/dt ^ e_3
    eps = (X.T * P - P.T * X)[0, 1]                    # eta = Psi = X^T P - P^T X = epsilon E_1 ^ E_2
    printed = F * e3dot - eps * e3.cross(e3dot)        # the remark as printed: +epsilon e_3 x de_3/dt
    corrected = F * e3dot + eps * e3.cross(e3dot)      # the correction: -epsilon e_3 x de_3/dt
    return {"printed": printed, "corrected": corrected}
