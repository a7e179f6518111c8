"""h2 (stop 85), fourth file: §7 on Ψ⁻¹(0), at the point (X, (I − XXᵀ)P) (twisted.at_point); truth: indep_d.py.

h2-gras-lambda (TRUE): on Ψ = 0, along the flow of H_neum,κ (every κ), Λ = XᵀAX − ẊᵀẊ, so λ = tr Λ of (neum-gras).
h2-gras-lambda-twin (FALSE for r < n; true at r = n where Ψ = 0 forces P = 0): XᵀAX + ẊᵀẊ.
h2-gras-sphere-projector (TRUE, r = n − 1): (neum-gras**) for the projector N = I − XXᵀ = e_n⊗e_n along (NE_XP)
  on Ψ = 0: N̈ = AN + NA − 2tr(AN)N + 2Ṅ² − 2tr(Ṅ²)N (from ë = Ae − ((e,Ae) + |ė|²)e, ėėᵀ = Ṅ² − ½tr(Ṅ²)N).
h2-gras-sphere-projector-twin (FALSE for n ≥ 2, r = n − 1): the A terms with the opposite sign
  (the potential +½(Ae, e) of the classical Neumann system in place of the printed −½(Ae, e)).
"""
from stiefelsym import admissible, claim, twisted


def H_neum(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def at_psi_zero(s):
    Ph = (s.In - s.X @ s.X.T) @ s.P
    return twisted.at_point(s, s.X, Ph)


def gras_lambda(s, sign):
    h = at_psi_zero(s)
    m = h.multiplier_flow(H_neum)
    return {"Psi = 0": h.Psi, "Lambda": m["Lambda"] - (h.X.T @ h.A @ h.X - sign * m.Xdot.T @ m.Xdot)}


@claim("h2-gras-lambda", kind="id", section="7", sizes=admissible(n_max=4))
def gras_lambda_true(s):
    """On Ψ = 0, Λ = XᵀAX − ẊᵀẊ along the flow of H_neum,κ for every κ."""
    return gras_lambda(s, 1)


@claim("h2-gras-lambda-twin", kind="id", section="7", sizes=admissible(n_max=4))
def gras_lambda_twin(s):
    """FALSE for r < n: XᵀAX + ẊᵀẊ."""
    return gras_lambda(s, -1)


NN1 = admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1")


def sphere_projector(s, sign):
    h = at_psi_zero(s)
    f = h.dirac_flow(H_E)
    X, P, A = h.X, h.P, h.A
    N = h.In - X @ X.T
    Nd = -(f.Xdot @ X.T + X @ f.Xdot.T)
    Ndd = -(f.Pdot @ X.T + 2 * P @ P.T + X @ f.Pdot.T)      # Xdot = P along (NE_XP)
    rhs = sign * (A @ N + N @ A - 2 * h.tr(A @ N) * N) + 2 * Nd @ Nd - 2 * h.tr(Nd @ Nd) * N
    return {"Xdot = P": f.Xdot - P, "N''": Ndd - rhs}


@claim("h2-gras-sphere-projector", kind="id", section="7", sizes=NN1)
def sphere_projector_true(s):
    """r = n − 1, Ψ = 0: N̈ = AN + NA − 2tr(AN)N + 2Ṅ² − 2tr(Ṅ²)N for N = I − XXᵀ along (NE_XP)."""
    return sphere_projector(s, 1)


@claim("h2-gras-sphere-projector-twin", kind="id", section="7", sizes=NN1)
def sphere_projector_twin(s):
    """FALSE: −(AN + NA) + 2tr(AN)N."""
    return sphere_projector(s, -1)
