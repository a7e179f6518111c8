"""The derivative pass against derivatives worked out by hand: every method evaluates the graph the pass
makes, so a wrong rule would give the same wrong verdict under every method.  Every claim here is TRUE (an
ambient directional derivative along a generic direction V, W of X, P, which need not be tangent).
Each docstring gives the formula."""
from stiefelsym import admissible, claim, block, det, elementary

SZ = admissible(n_max=3, n_min=2, r_min=2)


def M_of(t):
    return t.X.T @ t.A @ t.X + t.Ir


@claim("s75-d-inv-trace", kind="id", sizes=SZ)
def d_inv_trace(s):
    """d tr(M⁻¹) = −tr(M⁻¹ Ṁ M⁻¹), M = XᵀAX + I, Ṁ = VᵀAX + XᵀAV."""
    V = s.fresh("n", "r")
    M = M_of(s)
    Mi = M.inv()
    Md = V.T @ s.A @ s.X + s.X.T @ s.A @ V
    return {"w": s.d(lambda t: t.tr(M_of(t).inv()), {"X": V}) + s.tr(Mi @ Md @ Mi)}


@claim("s75-d-inv-matrix-transpose", kind="id", sizes=SZ)
def d_inv_matrix_transpose(s):
    """d (Mᵀ)⁻¹ with M = XᵀP + I (not symmetric): −(Mᵀ)⁻¹ Ṁᵀ (Mᵀ)⁻¹, Ṁ = VᵀP + XᵀW."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    M = s.X.T @ s.P + s.Ir
    Mti = M.T.inv()
    Md = V.T @ s.P + s.X.T @ W
    got = s.d(lambda t: (t.X.T @ t.P + t.Ir).T.inv(), {"X": V, "P": W})
    return {"w": got + Mti @ Md.T @ Mti}


@claim("s75-d-det", kind="id", sizes=SZ)
def d_det(s):
    """d det N = det N · tr(N⁻¹ Ṅ), N = XᵀP + I."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    N = s.X.T @ s.P + s.Ir
    Nd = V.T @ s.P + s.X.T @ W
    got = s.d(lambda t: det(t, t.X.T @ t.P + t.Ir), {"X": V, "P": W})
    return {"w": got - det(s, N) * s.tr(N.inv() @ Nd)}


@claim("s75-d-e2", kind="id", sizes=SZ)
def d_e2(s):
    """d e₂(N) = tr N tr Ṅ − tr(N Ṅ), N = XᵀP."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    N = s.X.T @ s.P
    Nd = V.T @ s.P + s.X.T @ W
    got = s.d(lambda t: elementary(t, t.X.T @ t.P, 2)[2], {"X": V, "P": W})
    return {"w": got - (s.tr(N) * s.tr(Nd) - s.tr(N @ Nd))}


@claim("s75-d-entries-slices", kind="id", sizes=SZ)
def d_entries_slices(s):
    """d (X[0,1]·P[1,0]) = V[0,1]P[1,0] + X[0,1]W[1,0]; d X[0:2, :] = V[0:2, :]."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.X[0, 1] * t.P[1, 0], {"X": V, "P": W})
    got2 = s.d(lambda t: t.X[0:2, :], {"X": V})
    return {"e": got - (V[0, 1] * s.P[1, 0] + s.X[0, 1] * W[1, 0]), "sl": got2 - V[0:2, :]}


@claim("s75-d-moving-resolvent", kind="id", sizes=SZ)
def d_moving_resolvent(s):
    """d R(μ) with μ = tr(XᵀAX): −μ̇ R(μ)², μ̇ = 2 tr(VᵀAX)."""
    V = s.fresh("n", "r")
    mu = s.tr(s.X.T @ s.A @ s.X)
    R = s.resolvent(mu)
    mud = s.tr(V.T @ s.A @ s.X) * 2
    got = s.d(lambda t: t.resolvent(t.tr(t.X.T @ t.A @ t.X)), {"X": V})
    return {"w": got + R @ R * mud}


@claim("s75-d-quotient-power", kind="id", sizes=SZ)
def d_quotient_power(s):
    """d (f³/g) = (3f² ḟ g − f³ ġ)/g², f = tr(XᵀP), g = tr(PᵀP) + 1."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    f = s.tr(s.X.T @ s.P)
    g = s.tr(s.P.T @ s.P) + 1
    fd = s.tr(V.T @ s.P) + s.tr(s.X.T @ W)
    gd = s.tr(W.T @ s.P) * 2
    got = s.d(lambda t: t.tr(t.X.T @ t.P) ** 3 / (t.tr(t.P.T @ t.P) + 1), {"X": V, "P": W})
    return {"w": got - (f * f * fd * g * 3 - f ** 3 * gd) / (g * g)}


@claim("s75-d-second", kind="id", sizes=SZ)
def d_second(s):
    """d²/dε² tr((XᵀX)²) along V = 2 tr((VᵀX + XᵀV)²) + 4 tr(XᵀX VᵀV)."""
    V = s.fresh("n", "r")
    F = lambda t: t.tr(t.X.T @ t.X @ t.X.T @ t.X)
    got = s.d(lambda t: t.d(F, {"X": V}), {"X": V})
    S = V.T @ s.X + s.X.T @ V
    return {"w": got - (s.tr(S @ S) * 2 + s.tr(s.X.T @ s.X @ V.T @ V) * 4)}


@claim("s75-d-block-inverse", kind="id", sizes=SZ)
def d_block_inverse(s):
    """d tr(B⁻¹) for B = [[M, N], [Nᵀ, I]], M = XᵀAX + 2I, N = XᵀP: −tr(B⁻¹ Ḃ B⁻¹)."""
    V = s.fresh("n", "r")

    def B_of(t):
        M = t.X.T @ t.A @ t.X + t.Ir * 2
        N = t.X.T @ t.P
        return block([[M, N], [N.T, t.Ir]])

    B = B_of(s)
    Md = V.T @ s.A @ s.X + s.X.T @ s.A @ V
    Nd = V.T @ s.P
    Bd = block([[Md, Nd], [Nd.T, s.Ir * 0]])
    Bi = B.inv()
    got = s.d(lambda t: t.tr(B_of(t).inv()), {"X": V})
    return {"w": got + s.tr(Bi @ Bd @ Bi)}


@claim("s75-d-phi-psi-ainv", kind="id", sizes=SZ)
def d_phi_psi_ainv(s):
    """dΦ = WXᵀ + PVᵀ − VPᵀ − XWᵀ; dΨ = VᵀP + XᵀW − WᵀX − PᵀV; d(A⁻¹X) = A⁻¹V."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    T = {"X": V, "P": W}
    return {"phi": s.d(lambda t: t.Phi, T) - (W @ s.X.T + s.P @ V.T - V @ s.P.T - s.X @ W.T),
            "psi": s.d(lambda t: t.Psi, T) - (V.T @ s.P + s.X.T @ W - W.T @ s.X - s.P.T @ V),
            "ainv": s.d(lambda t: t.Ainv @ t.X, T) - s.Ainv @ V}


@claim("s75-d-operator", kind="id", sizes=SZ)
def d_operator(s):
    """d tr(Φ 𝔸(Φ)) = 2 tr(Φ̇ 𝔸(Φ)) (𝔸 symmetric under the trace)."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    AA = s.sym_operator()
    Phid = W @ s.X.T + s.P @ V.T - V @ s.P.T - s.X @ W.T
    got = s.d(lambda t: t.tr(t.Phi @ AA(t.Phi)), {"X": V, "P": W})
    return {"w": got - s.tr(Phid @ AA(s.Phi)) * 2}
