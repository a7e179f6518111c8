"""(C-eq) of Appendix 2: the r-coupled Neumann system.  As printed, the last term of the equation
for Q' is Q Pi; the correction has Y Pi.  The check: the printed flow must keep the constraint
Y^T Q + Q^T Y = 0, i.e. its derivative along the flow must vanish."""

CHECK = "d(YᵀQ + QᵀY)/dt along (7) §10"


def residuals(W):
    X, P, Y, Q, A, kappa = W["X"], W["P"], W["Y"], W["Q"], W["A"], W["kappa"]
    c = 1 + 2 * kappa
    S = (X.T * A * Y + Y.T * A * X) / 2
    Pi = S - Q.T * Q                                   # (C-L)
    Ydot = Q - c * Y * Q.T * Y                         # (C-eq)

    def kept(Qdot):
        return Ydot.T * Q + Y.T * Qdot + Qdot.T * Y + Q.T * Ydot

    printed = -A * X + c * Q * Y.T * Q + Q * Pi        # (C-eq) as printed
    corrected = -A * X + c * Q * Y.T * Q + Y * Pi      # the correction: Y Pi
    return {"printed": kept(printed), "corrected": kept(corrected)}
