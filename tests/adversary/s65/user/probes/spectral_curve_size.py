# ruff: noqa
"""Probe: the printed spectral curve |a(lambda) L*_neum(lambda) - w I_n| (Section 8) subtracts an n x n identity
from the 2r x 2r matrix a L*; as printed it is ill-typed (the engine refuses it); with I_{2r} it is the
characteristic polynomial whose w^{2r-2} coefficient is a^2 e_2(L*) = a * I_2 (checked against I_2)."""
from stiefelsym import admissible, block, claim, elementary

S = admissible(n_max=4, n_min=2, where=lambda n, r: 2 * r != n, condition="2r != n (else I_n and I_2r have the same size)")


def Lstar(s):
    R = s.resolvent(s.lam)
    X, P = s.X, s.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, P.T @ R @ X]])


@claim("s65p-curve-as-printed", kind="id", sizes=S)
def curve_as_printed(s):
    """|a L* - w I_n| with I_n as printed: its (1,1) entry minus the same entry with the 2r identity."""
    w = s.scalar("w")
    M = Lstar(s) - w * s.In
    return {"entry": M[0, 0] - (Lstar(s)[0, 0] - w)}


@claim("s65p-curve-i2", kind="id", sizes=admissible(n_max=4, n_min=1))
def curve_i2(s):
    """e_2(L*) = sum_i |X_i|^2/(lam - a_i) + sum_{i<j} Phi_ij^2/((lam - a_i)(lam - a_j)): I_2 = a e_2(L*)."""
    R = s.resolvent(s.lam)
    e2 = elementary(s, Lstar(s), 2)[2]
    Phi = s.Phi
    rhs = s.tr(s.X.T @ R @ s.X) + s.tr(R @ Phi @ R @ Phi.T) / 2
    return {"e2 - I2/a": e2 - rhs}
