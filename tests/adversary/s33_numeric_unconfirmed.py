"""Route K (a term absorbed by an exact constant, c = 10^20) where the exact confirmation of a `numeric`
verdict does not run: it runs at n <= 12 (methods.FLOAT_CONFIRM_N) and only without options, so at (13, 2),
and at (3, 2) under any --hard case (even one that changes no parameter of the claim: "an ordinary random
point"), float and ball say `numeric` for these false claims."""
from stiefelsym import admissible, claim

C = 10 ** 20


@claim("adv-s33-absorb-X", kind="id", sizes=admissible(n_max=13), statement="(cX + X) - cX = 0, c = 10^20")
def absorb_x(s):
    """False: the residual is X."""
    return {"r": (s.X * C + s.X) - s.X * C}


@claim("adv-s33-absorb-trace", kind="id", sizes=admissible(n_max=13), statement="tr((cA + I) - cA) = 0, c = 10^20")
def absorb_trace(s):
    """False: the residual is n."""
    return {"r": s.tr((s.A * C + s.In) - s.A * C)}


@claim("adv-s33-absorb-phi", kind="id", sizes=admissible(n_max=13),
       statement="(c Phi + [XX^T, A]) - c Phi = 0, c = 10^20")
def absorb_phi(s):
    """False: the residual is [XXᵀ, A]."""
    M = s.X @ s.X.T
    return {"r": (s.Phi * C + (M @ s.A - s.A @ M)) - s.Phi * C}
