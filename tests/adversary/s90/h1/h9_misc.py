# ruff: noqa: F401
"""h9: invariance under group elements (Cayley), spectral-curve coefficients, refusal probes."""
from stiefelsym import admissible, block, claim, comm, elementary

SZ = admissible(n_max=4)
SZ2 = admissible(n_max=4, n_min=2)


def cayley(s, w, I):
    return (I - w) @ (I + w).inv()


@claim("h9-gram-so-n-invariant", paper=("SO(n)-inv", "left_action"), kind="geo", sizes=SZ2)
def gram_inv(s):
    """(gP)ᵀ(gP) = PᵀP and Ψ(gX, gP) = Ψ(X, P) for g = (I − ξ)(I + ξ)⁻¹ ∈ SO(n)."""
    g = cayley(s, s.xi, s.In)
    X, P = g @ s.X, g @ s.P
    return {"gram": P.T @ P - s.P.T @ s.P, "psi": (X.T @ P - P.T @ X) - s.Psi}


@claim("h9-potential-so-n-invariant-TWIN", paper=("SO(n)-inv", "Neumann_potential"), kind="geo", sizes=SZ2)
def pot_inv(s):
    """(false twin) tr((gX)ᵀA(gX)) = tr(XᵀAX) for g ∈ SO(n)."""
    g = cayley(s, s.xi, s.In)
    X = g @ s.X
    return {"V": s.tr(X.T @ s.A @ X) - s.tr(s.X.T @ s.A @ s.X)}


@claim("h9-neumann-so-r-invariant", paper=("neumann", "right_action"), kind="geo", sizes=SZ)
def neum_inv(s):
    """H_neum,κ(XQ, PQ) = H_neum,κ(X, P) for Q = (I − η)(I + η)⁻¹ ∈ SO(r)."""
    Q = cayley(s, s.eta, s.Ir)
    def H(X, P):
        K = X.T @ P
        return s.tr(P.T @ P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(K @ K) + s.tr(X.T @ s.A @ X) / 2
    return {"H": H(s.X @ Q, s.P @ Q) - H(s.X, s.P)}


@claim("h9-phi-so-r-invariant-TWIN", paper=("momentum_map", "right_action"), kind="geo", sizes=SZ)
def phi_inv_twin(s):
    """(false twin) Ψ(XQ, PQ) = Ψ(X, P) for Q ∈ SO(r) (Ψ is equivariant, not invariant)."""
    Q = cayley(s, s.eta, s.Ir)
    X, P = s.X @ Q, s.P @ Q
    return {"psi": (X.T @ P - P.T @ X) - s.Psi}


def Ls(t, lam):
    R = t.resolvent(lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


@claim("h9-spectral-odd-coefficients", paper="2r-integrals", kind="id", sizes=SZ)
def odd_coeffs(s):
    """In det(wI − L*(λ)) the coefficients e₁ and e₃ vanish on T*V."""
    e = elementary(s, Ls(s, s.lam), 3)
    return {"e1": e[1], "e3": e[3]}


@claim("h9-spectral-e2-TWIN", paper="2r-integrals", kind="id", sizes=SZ)
def e2_twin(s):
    """(false twin) e₂(L*(λ)) = −tr(XᵀR P)² ... stated as e₂ = 0."""
    e = elementary(s, Ls(s, s.lam), 2)
    return {"e2": e[2]}


@claim("h9-probe-inv-spelling", paper="LA3", kind="id", sizes=SZ)
def probe_inv(s):
    """Same as tr L*(λ) = 0 but with (λI − A)⁻¹ written via .inv() (free should refuse with the spelling)."""
    R = (s.lam * s.In - s.A).inv()
    X, P = s.X, s.P
    return {"tr": s.tr(-(X.T @ R @ P)) + s.tr(P.T @ R @ X)}
