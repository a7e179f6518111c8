"""h81: the false twins (one change each) of claims.py.  Each is stated where the numpy script finds it false."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, block, claim, comm, det
from stiefelsym.brackets import SO_N, SO_R, lambda1, lambda2, lie_poisson, skew, sym

from _h81_helpers import H_neum, Phi, Psi, Theta, gl_functions, so_n_functions, so_r_functions


@claim("n81-collective-phi", kind="pb", sizes=admissible(n_max=4, n_min=3, condition="n >= 3"))
def collective_phi(s):
    """Twin: the (−) Lie–Poisson field in place of (+) (so(2) is abelian: true at n = 2)."""
    T = lie_poisson(SO_N, -1)
    out = {}
    for name, h in so_n_functions():
        flow = s.dirac_flow(h.pullback(Phi))
        G = skew(h.grad(s, s.Phi))
        out[f"{name}: Xdot - G X"] = flow["X"] - G @ s.X
        out[f"{name}: Pdot - G P"] = flow["P"] - G @ s.P
        out[f"{name}: Phidot - sharp+"] = s.d(Phi, flow) - T.sharp(s, s.Phi, h.grad(s, s.Phi))
    return out


@claim("n81-collective-psi", kind="pb", sizes=admissible(n_max=4, r_min=3, condition="r >= 3"))
def collective_psi(s):
    """Twin: the (+) Lie–Poisson field in place of (−) (so(r) abelian for r <= 2)."""
    T = lie_poisson(SO_R, 1)
    out = {}
    for name, f in so_r_functions():
        flow = s.dirac_flow(f.pullback(Psi))
        G = skew(f.grad(s, s.Psi))
        out[f"{name}: Xdot - X G"] = flow["X"] - s.X @ G
        out[f"{name}: Pdot - P G"] = flow["P"] - s.P @ G
        out[f"{name}: Psidot - sharp-"] = s.d(Psi, flow) - T.sharp(s, s.Psi, f.grad(s, s.Psi))
    return out


@claim("n81-theta-related-flows", kind="pb", sizes=admissible(n_max=4, n_min=2))
def theta_related_flows(s):
    """Twin: Λ2 in place of Λ1."""
    T = lambda2()
    out = {}
    for name, F in gl_functions():
        flow = s.dirac_flow(F.pullback(Theta))
        out[f"{name}: Thetadot - Lambda1 sharp"] = s.d(Theta, flow) - T.sharp(s, Theta(s), F.grad(s, Theta(s)))
    return out


@claim("n81-neumann-chain-rule", kind="pb", sizes=admissible(n_max=4, n_min=2, where=lambda n, r: r < n, condition="r < n"))
def neumann_chain_rule(s):
    """Twin: [A, XXᵀ] in place of [XXᵀ, A]."""
    flow = s.dirac_flow(H_neum)
    out = {}
    for name, h in so_n_functions():
        out[f"{name}: d h(Phi) - <grad h, [XX^T, A]>"] = (
            s.d(h.pullback(Phi), flow) - s.killing(h.grad(s, s.Phi), comm(s.A, s.X @ s.X.T)))
    for name, f in so_r_functions():
        out[f"{name}: d f(Psi)"] = s.d(f.pullback(Psi), flow)
    return out


@claim("n81-phi-minor-pluecker", kind="geo",
       sizes=admissible(n_max=5, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def phi_minor_pluecker(s):
    """Twin: the Plücker coordinate not squared."""
    k = 2 * int(s.r)
    Phi_I = s.Phi[0:k, 0:k]
    M = block([[s.X[0:k, 0:int(s.r)], s.P[0:k, 0:int(s.r)]]])
    d = det(s, M)
    return {"minor of Phi - (Pluecker)^2": det(s, Phi_I) - d}


@claim("n81-r-equals-n", kind="id",
       sizes=admissible(n_max=5, where=lambda n, r: r == n, condition="r = n"))
def r_equals_n(s):
    """Twin: A² in place of A in the potential."""
    return {"tr X^T A X - tr A": s.tr(s.X.T @ s.A @ s.A @ s.X) - s.tr(s.A),
            "Phi - X Psi X^T": s.Phi - s.X @ s.Psi @ s.X.T}


@claim("n81-psi-zero-iff", kind="id", sizes=admissible(n_max=5, r_min=2, condition="r >= 2"))
def psi_zero_iff(s):
    """Twin: Ψ = 2PᵀX (at r = 1 both vanish)."""
    return {"Psi - 2 X^T P": s.Psi - 2 * (s.P.T @ s.X)}


@claim("n81-phi-rank", kind="dim",
       sizes=admissible(n_max=5, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def phi_rank(s):
    """Twin: rank 2r − 1."""
    return {"rank Phi": Rank(s.Phi, 2 * int(s.r) - 1)}


@claim("n81-lambda1-semidirect", kind="pb", sizes=admissible(n_max=4, n_min=2))
def lambda1_semidirect(s):
    """Twin: v̇ = [v, ξ] in place of [ξ, v]."""
    T = lambda1()
    x = s.generic("x", "n", "n")
    h, v = skew(x), sym(x)
    out = {}
    for name, F in gl_functions():
        G = F.grad(s, x)
        xi, eta = skew(G), sym(G)
        out[f"{name}: sharp - semidirect"] = T.sharp(s, x, G) - (comm(xi, h) + comm(eta, v) + comm(v, xi))
    return out


@claim("n81-submersion-psi-conserved", kind="pb", sizes=admissible(n_max=4, n_min=3))
def submersion_psi_conserved(s):
    """Twin: Φ in place of Ψ (Φ is not conserved by a non-invariant h)."""
    hs = so_n_functions()
    h = hs[0][1] + hs[1][1]
    flow = s.dirac_flow(h.pullback(Phi))
    return {"Psidot": s.d(Phi, flow)}
