"""s.resolvent(mu) = (mu I_n − A)^{-1} assumes mu is not an eigenvalue of A.  The dimension-free scene stands a
moving mu (a scalar polynomial of the point) for a fresh symbol m: "R_m's rules hold for every value of m, so an
identity they give holds at m = mu(X, P)" (free/scene.py _spectral_parameter), without asking whether mu I − A is
invertible there.  mu = tr(X^T A X) at n = r = 1 is x²a₁ = a₁ on T*V: mu I − A = 0, R does not exist, and the
statement R(mu)(mu I − A) = I has no value (the exact method: a division by zero, error).  Free: "proved (all n, r)"
while (1,1) is among the claim's sizes (as a division by n − 1 would be refused: review s78/review #8-#10)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=2)


@claim("r4-res-eig-n1", kind="id", sizes=SZ)
def res_eig(s):
    mu = s.tr(s.X.T @ s.A @ s.X)
    R = s.resolvent(mu)
    return {"R(mu)(mu I - A) - I": R @ (s.scalar_matrix(mu, s.n, "n") - s.A) - s.In}


@claim("r4-res-eig-trace", kind="id", sizes=SZ)
def res_eig_trace(s):
    """tr(X^T (mu I − A) R(mu) X) = tr(X^T X) = r: at (1,1) the left side is 0·(1/0)"""
    mu = s.tr(s.X.T @ s.A @ s.X)
    R = s.resolvent(mu)
    return {"tr(X^T (mu I - A) R X) - r": s.tr(s.X.T @ (s.scalar_matrix(mu, s.n, "n") - s.A) @ R @ s.X) - s.tr(s.Ir)}
