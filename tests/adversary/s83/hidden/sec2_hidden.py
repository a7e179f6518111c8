"""h3 hidden statements on §2 of the paper (constraints, the Dirac bracket, momentum maps, multipliers).
Every statement comes as an honest version (id h3-...) and a false twin (id h3-...-twin, one change).
Truths are derived in the docstrings and checked numerically by derive_numpy.py.in (logs/derive_numpy.log)."""
from stiefelsym import Rank, admissible, claim, comm


def H_lin(t):
    """H = tr(UᵀX) + tr(VᵀP), U, V generic: its differential at a point is arbitrary."""
    U = t.generic("U", "n", "r")
    V = t.generic("V", "n", "r")
    return t.tr(U.T @ t.X) + t.tr(V.T @ t.P)


def F_gram(t):
    """tr(S XᵀX), S a generic symmetric r×r matrix: a combination of the constraints F_ij."""
    S = t.generic("S", "r", "r", "sym")
    return t.tr(S @ t.X.T @ t.X)


def G_mixed(t):
    """tr(T (XᵀP + PᵀX)), T generic symmetric: a combination of the constraints G_ij."""
    T = t.generic("T", "r", "r", "sym")
    return t.tr(T @ (t.X.T @ t.P + t.P.T @ t.X))


# --- A1: the constraints are Casimirs of the Dirac bracket ------------------------------------

@claim("h3-casimir-constraints", kind="pb", section="2", sizes=admissible(5))
def constraints_are_casimirs(s):
    """(Dirac_bracket): {F_k, f} = {F_k, f}_0 − Σ {F_k, F_i}_0 C^{ij} {F_j, f}_0 = {F_k, f}_0 − δ_kj {F_j, f}_0 = 0
    for every constraint F_k and any f.  So {tr(S XᵀX), H} = 0 and {tr(T(XᵀP + PᵀX)), H} = 0 for every H
    (taken linear with generic coefficients, which gives an arbitrary differential)."""
    return {"{F_1, H}": s.bracket(F_gram, H_lin), "{F_2, H}": s.bracket(G_mixed, H_lin)}


@claim("h3-casimir-constraints-twin", kind="pb", section="2", sizes=admissible(5))
def constraints_are_casimirs_twin(s):
    """FALSE twin: the same for the canonical bracket {·,·}_0: {tr(S XᵀX), H}_0 = tr((2XS)ᵀV) ≠ 0."""
    return {"{F_1, H}_0": s.canonical_bracket(F_gram, H_lin), "{F_2, H}": s.bracket(G_mixed, H_lin)}


# --- A2: Dirac brackets of the coordinates -----------------------------------------------------

def fU(t):
    return t.tr(t.generic("U", "n", "r").T @ t.X)


def gWX(t):
    return t.tr(t.generic("W", "n", "r").T @ t.X)


def gWP(t):
    return t.tr(t.generic("W", "n", "r").T @ t.P)


@claim("h3-dirac-coordinates", kind="pb", section="2", sizes=admissible(5))
def dirac_brackets_of_coordinates(s):
    """The Dirac flow of g = tr(WᵀP) is (dot_XP): Ẋ = W − XΠ, with Π = sym(XᵀW) fixed by d(XᵀX)/dt = 0.
    Hence {tr(UᵀX), tr(WᵀP)} = d/dt tr(UᵀX) = tr(UᵀW) − ½ tr(UᵀX(XᵀW + WᵀX)).  The flow of tr(WᵀX) has
    Ẋ = ∂/∂P = 0 − XΠ with Π = 0, so positions commute: {tr(UᵀX), tr(WᵀX)} = 0."""
    U, W, X = s.generic("U", "n", "r"), s.generic("W", "n", "r"), s.X
    return {"{x, x}": s.bracket(fU, gWX),
            "{x, p}": s.bracket(fU, gWP) - (s.tr(U.T @ W) - s.tr(U.T @ X @ (X.T @ W + W.T @ X)) / 2)}


@claim("h3-dirac-coordinates-twin", kind="pb", section="2", sizes=admissible(5))
def dirac_brackets_of_coordinates_twin(s):
    """FALSE twin: the factor ½ of the projection dropped."""
    U, W, X = s.generic("U", "n", "r"), s.generic("W", "n", "r"), s.X
    return {"{x, x}": s.bracket(fU, gWX),
            "{x, p}": s.bracket(fU, gWP) - (s.tr(U.T @ W) - s.tr(U.T @ X @ (X.T @ W + W.T @ X)))}


# --- A3: the constraint bracket matrix has full rank r(r+1) at every point ------------------

@claim("h3-constraint-matrix-rank", kind="dim", section="2", sizes=admissible(5))
def constraint_matrix_full_rank(s):
    """{F_i, F_j}_0 in the order (F, G): {F, F}_0 = 0, {F_ij, G_kl}_0 built from XᵀX = I, so the matrix is
    [[0, a], [−aᵀ, b]] with a constant invertible on T*V: det = det(a)², a nonzero constant.  Its rank is r(r+1)
    at every point (the Dirac bracket is defined everywhere on T*V)."""
    r = int(s.r)
    return {"rank C0": Rank(s.mat(s.constraint_bracket_matrix()), r * (r + 1), generic=False)}


@claim("h3-constraint-matrix-rank-twin", kind="dim", section="2", sizes=admissible(5))
def constraint_matrix_full_rank_twin(s):
    """FALSE twin: rank r(r+1) − 1."""
    r = int(s.r)
    return {"rank C0": Rank(s.mat(s.constraint_bracket_matrix()), r * (r + 1) - 1, generic=False)}


# --- A4: rank of d(constraints, Φ): the SO(n)-orbits of T*V -----------------------------------

def so_dim(m):
    return m * (m - 1) // 2 if m > 1 else 0


def cond_and_phi(t):
    return [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X, t.Phi]


@claim("h3-orbit-rank", kind="dim", section="2", sizes=admissible(5))
def constraints_and_momentum_rank(s):
    """rank [dF; dΦ] = rank dF + rank(dΦ on ker dF = T(T*V)) = r(r+1) + dim of a generic SO(n)-orbit in T*V
    (dΦ_x(v) paired with ξ is ω(ξ·x, v): its rank on T_x(T*V) is dim so(n)·x).  The stabilizer of a generic (X, P)
    fixes span(X, P) (dimension min(2r, n)), so it is SO(n − 2r) for n > 2r and trivial otherwise:
    rank = r(r+1) + dim so(n) − dim so(max(n − 2r, 0))."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(s.mat(s.jacobian(cond_and_phi)), r * (r + 1) + so_dim(n) - so_dim(max(n - 2 * r, 0)))}


@claim("h3-orbit-rank-twin", kind="dim", section="2", sizes=admissible(5))
def constraints_and_momentum_rank_twin(s):
    """FALSE twin: one more."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(s.mat(s.jacobian(cond_and_phi)), r * (r + 1) + so_dim(n) - so_dim(max(n - 2 * r, 0)) + 1)}


# --- A5: the flow of Φ_ξ moves Φ by ad_ξ and keeps Ψ --------------------------------------

def Phi_xi(t):
    return t.killing(t.Phi, t.xi)


@claim("h3-phi-flow-adjoint", kind="pb", section="2", sizes=admissible(5))
def phi_flow_is_adjoint(s):
    """Φ_ξ = −½tr(Φξ): ∂Φ_ξ/∂P = ξX, ∂Φ_ξ/∂X = ξP (from tr(PXᵀξ) = ⟨P, ξᵀX⟩ and tr(XPᵀξ) = ⟨P, ξX⟩), Π = sym(XᵀξX) = 0,
    so the Dirac flow is (ξX, ξP) and dΦ/dt = ξPXᵀ + PXᵀξᵀ − ξXPᵀ − XPᵀξᵀ = [ξ, Φ]; dΨ/dt = Xᵀξᵀ... = XᵀξᵀξP... =
    (ξX)ᵀP + XᵀξP − (ξP)ᵀX − PᵀξX = 0 (ξ skew)."""
    flow = s.dirac_flow(Phi_xi)
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.xi, s.Phi), "dPsi/dt": s.d(lambda t: t.Psi, flow)}


@claim("h3-phi-flow-adjoint-twin", kind="pb", section="2", sizes=admissible(5, n_min=3, condition="n >= 3 (so(2) is abelian)"))
def phi_flow_is_adjoint_twin(s):
    """FALSE twin (n ≥ 3): the commutator in the other order."""
    flow = s.dirac_flow(Phi_xi)
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.Phi, s.xi), "dPsi/dt": s.d(lambda t: t.Psi, flow)}
