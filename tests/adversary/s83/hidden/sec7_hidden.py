"""h3 hidden statements on §7 (reduction to Grassmannians)."""
from stiefelsym import Rank, admissible, claim
from stiefelsym.bases import matrix_of, so_basis


def horizontal(s, xi):
    return (s.In - s.X @ s.X.T) @ xi @ s.X


def so_coords(M, m):
    return [M[i, j] for i in range(m) for j in range(i + 1, m)]


def stabilizer_kernel(s):
    """Kernel vectors of ξ ↦ (I − XXᵀ)ξX: ξ = XηXᵀ (η ∈ so(r)) and ξ = QEQ (Q = I − XXᵀ, E ∈ so(n))."""
    n = int(s.n)
    Q = s.In - s.X @ s.X.T
    vecs = [so_coords(s.X @ eta @ s.X.T, n) for eta in (so_basis(s, "r") if int(s.r) > 1 else [])]
    vecs += [so_coords(Q @ E @ Q, n) for E in so_basis(s, "n")]
    return s.mat([list(row) for row in zip(*vecs)])


@claim("h3-grassmannian-dim", kind="dim", section="7", sizes=admissible(5, n_min=2))
def grassmannian_dim(s):
    """The SO(n)-action on G(n, r) has differential ξ ↦ (I − XXᵀ)ξX ∈ Hom(span X, span X^⊥) at span X: onto,
    with kernel so(r) ⊕ so(n − r) (the stabilizer S(O(r)×O(n−r))), so its rank is dim G_{n,r} = r(n − r)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: horizontal(s, xi), so_basis(s, "n"))
    return {"rank": Rank(M, r * (n - r), kernel=stabilizer_kernel(s))}


@claim("h3-grassmannian-dim-twin-up", kind="dim", section="7", sizes=admissible(5, n_min=2))
def grassmannian_dim_twin_up(s):
    """FALSE twin: r(n − r) + 1."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: horizontal(s, xi), so_basis(s, "n"))
    return {"rank": Rank(M, r * (n - r) + 1, kernel=stabilizer_kernel(s))}


@claim("h3-grassmannian-dim-twin-down", kind="dim", section="7",
       sizes=admissible(5, n_min=2, where=lambda n, r: r < n, condition="r < n"))
def grassmannian_dim_twin_down(s):
    """FALSE twin: r(n − r) − 1 (r < n)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: horizontal(s, xi), so_basis(s, "n"))
    return {"rank": Rank(M, r * (n - r) - 1, kernel=stabilizer_kernel(s))}


def H_quartic(t):
    X, A = t.X, t.A
    return t.tr(t.P.T @ t.P) / 2 + t.tr(X.T @ A @ A @ X) - t.tr(X.T @ A @ X @ X.T @ A @ X)


@claim("h3-quartic-potential", kind="id", section="7", sizes=admissible(5))
def quartic_potential(s):
    """tr(XᵀA²X) − tr(XᵀAXXᵀAX) = tr(XᵀA(I − XXᵀ)AX) = |(I − XXᵀ)AX|² (a projector), and the quartic
    Hamiltonian is right O(r)-invariant, so Ψ is conserved along its Dirac flow (Ψ⁻¹(0) is invariant)."""
    X, A = s.X, s.A
    flow = s.dirac_flow(H_quartic)
    return {"potential": s.tr(X.T @ A @ A @ X) - s.tr(X.T @ A @ X @ X.T @ A @ X) - s.tr(X.T @ A @ (s.In - X @ X.T) @ A @ X),
            "dPsi/dt": s.d(lambda t: t.Psi, flow)}


@claim("h3-quartic-potential-twin", kind="id", section="7",
       sizes=admissible(5, where=lambda n, r: r < n, condition="r < n"))
def quartic_potential_twin(s):
    """FALSE twin (r < n): (XXᵀ − I) in place of (I − XXᵀ)."""
    X, A = s.X, s.A
    flow = s.dirac_flow(H_quartic)
    return {"potential": s.tr(X.T @ A @ A @ X) - s.tr(X.T @ A @ X @ X.T @ A @ X) - s.tr(X.T @ A @ (X @ X.T - s.In) @ A @ X),
            "dPsi/dt": s.d(lambda t: t.Psi, flow)}


def H_neum(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_neum0(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("h3-neumann-kappa-shift", kind="id", section="7", sizes=admissible(5))
def neumann_kappa_shift(s):
    """H_neum,κ − H_neum,0 = κ·½⟨Ψ,Ψ⟩, whose Dirac flow is κ(XΨ, PΨ); so the κ-Neumann flows differ from the κ = 0
    flow by κ(XΨ, PΨ) and coincide on Ψ⁻¹(0) (the reduction to T*G_{n,r})."""
    f, g = s.dirac_flow(H_neum), s.dirac_flow(H_neum0)
    return {"dX": f.Xdot - g.Xdot - s.kappa * s.X @ s.Psi, "dP": f.Pdot - g.Pdot - s.kappa * s.P @ s.Psi}


@claim("h3-neumann-kappa-shift-twin", kind="id", section="7", sizes=admissible(5, r_min=2, condition="r >= 2"))
def neumann_kappa_shift_twin(s):
    """FALSE twin (r ≥ 2): 2κ in the X part."""
    f, g = s.dirac_flow(H_neum), s.dirac_flow(H_neum0)
    return {"dX": f.Xdot - g.Xdot - 2 * s.kappa * s.X @ s.Psi, "dP": f.Pdot - g.Pdot - s.kappa * s.P @ s.Psi}
