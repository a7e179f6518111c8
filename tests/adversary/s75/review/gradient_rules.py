"""Reverse-mode gradients, Dirac flows and brackets against forward derivatives and known identities, on
functions with inverses, determinants, entries, slices, blocks, a moving resolvent and the operator letter.
All TRUE: ⟨∇H, (V, W)⟩ = dH(V, W) (ambient), dH/dt = 0 along H's own Dirac flow, {F, G} = −{G, F}, and the
Jacobi identity of the Dirac bracket on T*V."""
from stiefelsym import admissible, claim, block, det, elementary

SZ = admissible(n_max=3, n_min=2, r_min=2)


def H_inv(t):
    return t.tr((t.X.T @ t.A @ t.X + t.Ir).inv())


def H_det(t):
    return det(t, t.X.T @ t.P + t.Ir * 2)


def H_entries(t):
    return t.X[0, 1] * t.P[1, 0] + t.P[0, 0] * t.P[0, 0] * t.X[1, 1]


def H_slices(t):
    B = t.X[0:2, :]
    return t.tr(B.T @ B @ t.P.T @ t.P)


def H_block(t):
    M = t.X.T @ t.A @ t.X + t.Ir * 2
    N = t.X.T @ t.P
    return t.tr(block([[M, N], [N.T, t.Ir]]).inv())


def H_res(t):
    return t.tr(t.P.T @ t.resolvent(t.tr(t.X.T @ t.A @ t.X)) @ t.P)


def H_e2(t):
    return elementary(t, t.P.T @ t.A @ t.P + t.X.T @ t.P, 2)[2]


def H_quot(t):
    return t.tr(t.X.T @ t.A @ t.X) ** 2 / (t.tr(t.P.T @ t.A @ t.P) + 1)


FUNCS = {"inv": H_inv, "det": H_det, "entries": H_entries, "slices": H_slices, "block": H_block,
         "res": H_res, "e2": H_e2, "quot": H_quot}


@claim("s75-g-gradient-vs-d", kind="id", sizes=SZ)
def g_gradient_vs_d(s):
    """tr(H_Xᵀ V) + tr(H_Pᵀ W) = dH(V, W) for each H."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    out = {}
    for name, H in FUNCS.items():
        HX, HP = s.gradient(H)
        out[name] = s.tr(HX.T @ V) + s.tr(HP.T @ W) - s.d(H, {"X": V, "P": W})
    return out


@claim("s75-g-energy", kind="id", sizes=SZ)
def g_energy(s):
    """dH/dt = 0 along the Dirac flow of H, for each H."""
    return {name: s.d(H, s.dirac_flow(H)) for name, H in FUNCS.items()}


@claim("s75-g-antisym", kind="id", sizes=SZ)
def g_antisym(s):
    """{F, G} + {G, F} = 0 (Dirac bracket)."""
    pairs = [("inv", "entries"), ("det", "block"), ("res", "slices"), ("e2", "quot")]
    return {f"{a}-{b}": s.bracket(FUNCS[a], FUNCS[b]) + s.bracket(FUNCS[b], FUNCS[a]) for a, b in pairs}


@claim("s75-g-jacobi", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2))
def g_jacobi(s):
    """{F,{G,K}} + {G,{K,F}} + {K,{F,G}} = 0 for the Dirac bracket: TRUE."""
    F, G, K = H_entries, H_inv, H_slices
    b = s.bracket
    return {"jacobi": b(F, lambda t: t.bracket(G, K)) + b(G, lambda t: t.bracket(K, F))
            + b(K, lambda t: t.bracket(F, G))}
