"""The stop's own attempt on its change to the free method (a flow at a point of the claim's own keeps its
multipliers): false claims that read the multipliers at (X, −P) as if they were those at (X, P).

H = ½tr(PᵀP) + tr(XᵀAP): its term linear in P changes the multipliers with the sign of P, so
pm-lambda-same-f (Λ at (X, −P) equals Λ at (X, P)) is false; pm-lambda-shift-f (Λ at (X, −P) equals
XᵀAX + PᵀP for ½tr PᵀP + ½tr XᵀAX) is false wherever P ≠ 0.  Their controls: pm-pi-zero-t (Π = 0 at (X, −P) for
½tr PᵀP + ½tr XᵀAX) and pm-lambda-t (Λ = XᵀAX − PᵀP there) are true."""
from stiefelsym import admissible, claim, twisted

SZ = admissible(n_max=3)


def H_lin(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.P)


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("pm-lambda-same-f", kind="id", sizes=SZ)
def lambda_same(s):
    h = twisted.at_point(s, s.X, -s.P)
    return {"Lambda": h.multiplier_flow(H_lin)["Lambda"] - s.multiplier_flow(H_lin)["Lambda"]}


@claim("pm-lambda-shift-f", kind="id", sizes=SZ)
def lambda_shift(s):
    h = twisted.at_point(s, s.X, -s.P)
    return {"Lambda": h.multiplier_flow(H_E)["Lambda"] - (s.X.T @ s.A @ s.X + s.P.T @ s.P)}


@claim("pm-pi-zero-t", kind="id", sizes=SZ)
def pi_zero(s):
    return {"Pi": twisted.at_point(s, s.X, -s.P).multiplier_flow(H_E)["Pi"]}


@claim("pm-lambda-t", kind="id", sizes=SZ)
def lambda_t(s):
    h = twisted.at_point(s, s.X, -s.P)
    return {"Lambda": h.multiplier_flow(H_E)["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P)}
