"""h81: ten statements of the paper the catalog does not state (true), each with a twin in negatives.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, block, claim, comm, det
from stiefelsym.brackets import SO_N, SO_R, lambda1, lie_poisson, skew, sym

from _h81_helpers import H_neum, Phi, Psi, Theta, gl_functions, so_n_functions, so_r_functions


@claim("h81-collective-phi", paper=("momentum_map", "dot_XP2"), kind="pb", sizes=admissible(n_max=4))
def collective_phi(s):
    """§2 Prop. (momentum_map) with the chain rule of the proof of (dot_XP2), for any h on so(n): the Dirac flow
    of H = h∘Φ is Ẋ = skew(∇h(Φ))X, Ṗ = skew(∇h(Φ))P (Λ = Π = 0), and Φ̇ is the (+) Lie–Poisson Hamiltonian
    vector field of h at Φ.  By hand: dH = <∇h, dΦ> gives H_P = GX, H_X = −GP (G = skew ∇h), a vector field
    tangent to T*V; Φ̇ = [G, Φ], and ẋ = [∇h, x] is the (+) field ({<x,ξ>, h}^+ = <x, [ξ, ∇h]> = <[∇h, x], ξ>)."""
    T = lie_poisson(SO_N, 1)
    out = {}
    for name, h in so_n_functions():
        flow = s.dirac_flow(h.pullback(Phi))
        G = skew(h.grad(s, s.Phi))
        out[f"{name}: Xdot - G X"] = flow["X"] - G @ s.X
        out[f"{name}: Pdot - G P"] = flow["P"] - G @ s.P
        out[f"{name}: Phidot - sharp+"] = s.d(Phi, flow) - T.sharp(s, s.Phi, h.grad(s, s.Phi))
    return out


@claim("h81-collective-psi", paper=("momentum_right_map",), kind="pb", sizes=admissible(n_max=4))
def collective_psi(s):
    """§2 Prop. (momentum_right_map): the Dirac flow of F = f∘Ψ is Ẋ = X skew(∇f(Ψ)), Ṗ = P skew(∇f(Ψ)), and Ψ̇
    is the (−) Lie–Poisson field of f at Ψ.  By hand: dF = <G, dΨ> gives H_P = XG, H_X = −PG, Ψ̇ = [Ψ, G]
    = −[G, Ψ] (the (−) bracket)."""
    T = lie_poisson(SO_R, -1)
    out = {}
    for name, f in so_r_functions():
        flow = s.dirac_flow(f.pullback(Psi))
        G = skew(f.grad(s, s.Psi))
        out[f"{name}: Xdot - X G"] = flow["X"] - s.X @ G
        out[f"{name}: Pdot - P G"] = flow["P"] - s.P @ G
        out[f"{name}: Psidot - sharp-"] = s.d(Psi, flow) - T.sharp(s, s.Psi, f.grad(s, s.Psi))
    return out


@claim("h81-theta-related-flows", paper=("LAMBDA12",), kind="pb", sizes=admissible(n_max=4))
def theta_related_flows(s):
    """§6: 'Θ = Φ + XXᵀ defines the Poisson mapping between (T*V, {,}) and (gl(n), Λ1)', hence the Dirac flow of
    F∘Θ is Θ-related to the Λ1 Hamiltonian field of F: d/dt Θ = Λ1(·, ∇F)^♯ at Θ, for F on gl(n) not a Casimir
    (tr(x + C)³ with C generic, ½<x, x + xᵀ>)."""
    T = lambda1()
    out = {}
    for name, F in gl_functions():
        flow = s.dirac_flow(F.pullback(Theta))
        out[f"{name}: Thetadot - Lambda1 sharp"] = s.d(Theta, flow) - T.sharp(s, Theta(s), F.grad(s, Theta(s)))
    return out


@claim("h81-neumann-chain-rule", paper=("prep", "No", "neumann"), kind="pb", sizes=admissible(n_max=4))
def neumann_chain_rule(s):
    """§5 (prep) for every κ, through functions on so(n): d/dt h(Φ) = <∇h(Φ), [XXᵀ, A]> along (No), and f(Ψ) is
    conserved (Ψ is, 'for any κ') for f on so(r) not ad-invariant."""
    flow = s.dirac_flow(H_neum)
    out = {}
    for name, h in so_n_functions():
        out[f"{name}: d h(Phi) - <grad h, [XX^T, A]>"] = (
            s.d(h.pullback(Phi), flow) - s.killing(h.grad(s, s.Phi), comm(s.X @ s.X.T, s.A)))
    for name, f in so_r_functions():
        out[f"{name}: d f(Psi)"] = s.d(f.pullback(Psi), flow)
    return out


@claim("h81-phi-minor-pluecker", paper=("2r-integrals", "forms"), kind="geo",
       sizes=admissible(n_max=5, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def phi_minor_pluecker(s):
    """§8 after (2r-integrals): '|Φ|^{I_2r}_{I_2r} = (e₁∧…∧e_r∧p₁∧…∧p_r)²_{I_2r}', I = {1..2r}: Φ = M J Mᵀ with
    M = [X P], so the principal minor is det(M_I)² det J = det(M_I)²."""
    k = 2 * int(s.r)
    Phi_I = s.Phi[0:k, 0:k]
    M = block([[s.X[0:k, 0:int(s.r)], s.P[0:k, 0:int(s.r)]]])
    d = det(s, M)
    return {"minor of Phi - (Pluecker)^2": det(s, Phi_I) - d * d}


@claim("h81-r-equals-n", paper=("Neumann_potential", "dot_XP2"), kind="id",
       sizes=admissible(n_max=5, where=lambda n, r: r == n, condition="r = n"))
def r_equals_n(s):
    """§5 'the above potential is constant for r [= n]': tr(XᵀAX) = tr A; and at r = n (§3 Remark after
    (dot_XP2), T*SO(n)) the two momenta are conjugate: Φ = XΨXᵀ (P = XW, Φ = 2XWXᵀ, Ψ = 2W)."""
    return {"tr X^T A X - tr A": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A),
            "Phi - X Psi X^T": s.Phi - s.X @ s.Psi @ s.X.T}


@claim("h81-psi-zero-iff", paper=("momentum_right_map", "grassmannian"), kind="id", sizes=admissible(n_max=5))
def psi_zero_iff(s):
    """§7 '(X, P) belongs to Ψ⁻¹(0) iff XᵀP = 0': on T*V, Ψ = 2XᵀP (PᵀX = −XᵀP)."""
    return {"Psi - 2 X^T P": s.Psi - 2 * (s.X.T @ s.P)}


@claim("h81-phi-rank", paper=("dot_XP3*", "momentum_map"), kind="dim",
       sizes=admissible(n_max=5, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def phi_rank(s):
    """§4 after Thm man-dual ('on XᵀP = 0 ... rank r solutions of the Manakov system'): Φ = Σ p_i∧e_i has generic
    rank 2r for n ≥ 2r (M = [X P] of rank 2r, J invertible)."""
    return {"rank Phi": Rank(s.Phi, 2 * int(s.r))}


@claim("h81-lambda1-semidirect", paper=("LAMBDA12", "CPB"), kind="pb", sizes=admissible(n_max=4))
def lambda1_semidirect(s):
    """§6 'Λ1 corresponds to the canonical Lie–Poisson bracket of so(n) ⊕_ad Sym(n)': its Hamiltonian field of F
    at x = h + v, ∇F = ξ + η, is ḣ = [ξ, h] + [η, v], v̇ = [ξ, v] (for F = ½<h,h> − <A,v> this is (CPB)).  By
    hand: Λ1(ζ+θ, ξ+η) = <h,[ζ,ξ]> + <v,[ζ,η]> + <v,[θ,ξ]> = <[ξ,h] + [η,v], ζ> + <[ξ,v], θ>."""
    T = lambda1()
    x = s.generic("x", "n", "n")
    h, v = skew(x), sym(x)
    out = {}
    for name, F in gl_functions():
        G = F.grad(s, x)
        xi, eta = skew(G), sym(G)
        out[f"{name}: sharp - semidirect"] = T.sharp(s, x, G) - (comm(xi, h) + comm(eta, v) + comm(xi, v))
    return out


@claim("h81-submersion-psi-conserved", paper=("dot_XP2", "momentum_right_map", "submersion_metric"), kind="pb",
       sizes=admissible(n_max=4))
def submersion_psi_conserved(s):
    """§3 submersion metrics are right SO(r)-invariant (Φ and Ψ commute, §2): along the Dirac flow of h∘Φ for
    h = h_𝔸 + tr(μ + λA)³ (a sum of MatrixFunctions), Ψ is conserved."""
    hs = so_n_functions()
    h = hs[0][1] + hs[1][1]
    flow = s.dirac_flow(h.pullback(Phi))
    return {"Psidot": s.d(Psi, flow)}
