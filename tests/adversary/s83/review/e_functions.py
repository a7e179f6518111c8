"""Stop 83 review (h2): traced functions (s.d along a flow, s.gradient) whose bodies read the nodes of y of a
reassociated trace, or hold reassociable traces of their own (brief item 5).  -t- true, -f- false (one change).
d/dt tr(M [X Pᵀ, N]) = tr(M [Ẋ Pᵀ + X Ṗᵀ, N]) along any flow (product rule; M, N constant)."""
from stiefelsym import admissible, claim, comm

S = admissible(n_min=3, n_max=4, r_min=1, r_max=3)


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("adv-s83r-t-flow-reads-y", paper="adv", kind="id", sizes=S)
def t_flow(s):
    """True: the body of f reads C = [XPᵀ, N] (a top-level node, the y of tr(M C) and of tr(A C)); the derivative
    of f along the Neumann flow by the product rule."""
    M, N = s.generic("M", "n", "n"), s.generic("N", "n", "n")
    C = comm(s.X @ s.P.T, N)
    fl = s.dirac_flow(H)
    f = lambda t: t.tr(M @ comm(t.X @ t.P.T, N)) + t.tr(C @ t.X @ t.X.T)
    Xd, Pd = fl["X"], fl["P"]
    want = (s.tr(M @ comm(Xd @ s.P.T + s.X @ Pd.T, N)) + s.tr(C @ (Xd @ s.X.T + s.X @ Xd.T)))
    return {"d": s.d(f, fl) - want, "fused": s.tr(M @ C) + s.tr(s.A @ C) - s.tr((M + s.A) @ C)}


@claim("adv-s83r-f-flow-reads-y", paper="adv", kind="id", sizes=S)
def f_flow(s):
    """False: the product rule with the X Ṗᵀ term dropped."""
    M, N = s.generic("M", "n", "n"), s.generic("N", "n", "n")
    C = comm(s.X @ s.P.T, N)
    fl = s.dirac_flow(H)
    f = lambda t: t.tr(M @ comm(t.X @ t.P.T, N)) + t.tr(C @ t.X @ t.X.T)
    Xd = fl["X"]
    want = (s.tr(M @ comm(Xd @ s.P.T, N)) + s.tr(C @ (Xd @ s.X.T + s.X @ Xd.T)))
    return {"d": s.d(f, fl) - want, "fused": s.tr(M @ C) + s.tr(s.A @ C) - s.tr((M + s.A) @ C)}


@claim("adv-s83r-t-gradient-of-traces", paper="adv", kind="id", sizes=S)
def t_grad(s):
    """True: the gradient of h = Σ_z tr(K [X Pᵀ, z]) (family z ∈ {N, A, Φ}) in P is Σ_z [z, K]ᵀ... precisely
    d/dP tr(K (X Pᵀ z − z X Pᵀ)) = (z K − K z)ᵀ X... : tr(K X Pᵀ z) = tr(Pᵀ z K X) → ∂/∂P = z K X;
    tr(K z X Pᵀ) = tr(Pᵀ K z X) → K z X.  So h_P = Σ (zK − Kz) X."""
    K, N = s.generic("K", "n", "n"), s.generic("N", "n", "n")
    zs = [N, s.A, s.Phi]
    h = lambda t: sum(t.tr(K @ comm(t.X @ t.P.T, z)) for z in zs)
    hX, hP = s.gradient(h)
    want = (N @ K - K @ N) @ s.X + (s.A @ K - K @ s.A) @ s.X
    # the Φ term depends on X, P too (Φ of the scene t inside h is t's): keep only the P-gradient of the constant z's
    h2 = lambda t: t.tr(K @ comm(t.X @ t.P.T, N)) + t.tr(K @ comm(t.X @ t.P.T, s.A))
    g2X, g2P = s.gradient(h2)
    return {"P": g2P - want, "fam": s.tr(K @ comm(N, s.A)) + s.tr(s.Phi @ comm(N, s.A)) - s.tr((K + s.Phi) @ comm(N, s.A))}


@claim("adv-s83r-f-gradient-of-traces", paper="adv", kind="id", sizes=S)
def f_grad(s):
    """False: h_P with (K z − z K) for the A term (sign)."""
    K, N = s.generic("K", "n", "n"), s.generic("N", "n", "n")
    want = (N @ K - K @ N) @ s.X + (K @ s.A - s.A @ K) @ s.X
    h2 = lambda t: t.tr(K @ comm(t.X @ t.P.T, N)) + t.tr(K @ comm(t.X @ t.P.T, s.A))
    g2X, g2P = s.gradient(h2)
    return {"P": g2P - want}
