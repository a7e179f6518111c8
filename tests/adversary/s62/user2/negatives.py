"""False variants (plain claims: each should FAIL; a proved/checked/numeric here is a wrong verdict).
Stated only for 2 <= r < n, where each one is genuinely false (at r = 1 the c-terms vanish, at r = n XX^T = I)."""
from stiefelsym import Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

from common import hamiltonian, hand_flow

NEG = admissible(n_max=4, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n")


@claim("u2-neg-sign", kind="id", sizes=NEG)
def wrong_sign(s):
    """FALSE: Xdot = P + 2c XX^T P (sign of the c-term flipped)."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    return {"dX/dt": flow["X"] - (s.P + 2 * c * (s.X @ s.X.T @ s.P))}


@claim("u2-neg-missing", kind="id", sizes=NEG)
def missing_term(s):
    """FALSE: Pdot without the multiplier term X M^2."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    hand = hand_flow(s, c)
    M = s.X.T @ s.A @ s.X
    return {"dP/dt": flow["P"] - (hand["P"] - s.X @ M @ M)}


@claim("u2-neg-lax-order", kind="id", sizes=NEG)
def lax_wrong_order(s):
    """FALSE: d(XX^T)/dt = [XX^T, Phi] (commutator order reversed)."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    L = s.X @ s.X.T
    return {"dL/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(L, s.Phi)}


@claim("u2-neg-phi-neumann", kind="id", sizes=NEG)
def phi_neumann(s):
    """FALSE: dPhi/dt = [XX^T, A] (the quadratic Neumann law, wrong for the quartic potential)."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A)}


@claim("u2-neg-phi-conserved", kind="id", sizes=NEG)
def phi_conserved(s):
    """FALSE: Phi is conserved."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow)}


@claim("u2-neg-lambda", kind="id", sizes=NEG)
def lambda_sign(s):
    """FALSE: Lambda = M^2 + P^T P."""
    c = s.scalar("c")
    mult = s.multiplier_flow(hamiltonian(c))
    M = s.X.T @ s.A @ s.X
    return {"Lambda": mult["Lambda"] - (M @ M + s.P.T @ s.P)}


@claim("u2-neg-rank-ad-psi", kind="dim", sizes=NEG)
def rank_ad_psi_full(s):
    """FALSE: ad_Psi on so(r) has full rank dim so(r)."""
    r = int(s.r)
    M = matrix_of(s, lambda eta: comm(eta, s.Psi), so_basis(s, "r"), kind="skew")
    return {"rank ad_Psi": Rank(M, r * (r - 1) // 2)}


@claim("u2-neg-rank-phi", kind="dim", sizes=admissible(n_max=4, n_min=3, where=lambda n, r: n % 2 == 1 and 2 * r > n, condition="n odd, 2r > n"))
def rank_phi_n(s):
    """FALSE: rank Phi = min(2r, n) (forgets that a skew matrix has even rank)."""
    n, r = int(s.n), int(s.r)
    return {"rank Phi": Rank(s.Phi, min(2 * r, n))}


@claim("u2-neg-not", kind="not", expect="nonzero", sizes=NEG)
def psi_not_conserved(s):
    """FALSE 'not' statement: Psi is NOT conserved (it is) -- should be refuted (fails)."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    return {"dPsi/dt": s.d(lambda t: t.Psi, flow)}
