"""A new user's true statements of the paper, written independently of proofs/.

Run:  stiefelsym verify --claims tests/adversary/s74/newuser/true_claims.py --jobs 1 --max-n 4
"""
from stiefelsym import Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis


from nu_helpers import neumann_kappa, printed_No


@claim("nu-No-from-H", paper="No", kind="id", sizes=admissible(n_max=4))
def no_is_the_dirac_flow(s):
    """The Dirac flow of H_{neum,kappa} is (No) for every kappa."""
    flow = s.dirac_flow(neumann_kappa)
    printed = printed_No(s)
    return {"Xdot": flow["X"] - printed["X"], "Pdot": flow["P"] - printed["P"]}


@claim("nu-LA1-kappa", paper=("LA1", "LA2"), kind="lax", sizes=admissible(n_max=4))
def lax_of_neumann_any_kappa(s):
    """Along (No), at any kappa, dL/dt = [A(lambda), L(lambda)] with L = lambda Phi + X X^T - lambda^2 A, A = Phi - lambda A."""
    lam = s.lam
    L = lambda t: lam * t.Phi + t.X @ t.X.T - lam * lam * t.A
    Alax = s.Phi - lam * s.A
    return {"LA1": s.d(L, printed_No(s)) - comm(Alax, L(s))}


@claim("nu-trL2-conserved", paper="LA1", kind="id", sizes=admissible(n_max=4))
def spectral_invariant_conserved(s):
    """tr L(lambda)^2 and tr L(lambda)^3 are first integrals of (No)."""
    lam = s.lam
    def L(t):
        return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A
    flow = s.dirac_flow(neumann_kappa)
    return {"d tr L^2": s.d(lambda t: t.tr(L(t) @ L(t)), flow),
            "d tr L^3": s.d(lambda t: t.tr(L(t) @ L(t) @ L(t)), flow)}


@claim("nu-bracket-H-trL2", paper="LA1", kind="pb", sizes=admissible(n_max=3))
def bracket_with_h(s):
    """{tr L(lambda)^2, H_{neum,kappa}} = 0 in the Dirac bracket."""
    lam = s.lam
    def F(t):
        L = lam * t.Phi + t.X @ t.X.T - lam * lam * t.A
        return t.tr(L @ L)
    return {"{F,H}": s.bracket(F, neumann_kappa)}


@claim("nu-prep", paper="prep", kind="id", sizes=admissible(n_max=4))
def prep_both(s):
    """(prep): dPhi/dt = [XX^T, A] and d(XX^T)/dt = [Phi, XX^T] along (No)."""
    f = printed_No(s)
    XXt = s.X @ s.X.T
    return {"dPhi": s.d(lambda t: t.Phi, f) - comm(XXt, s.A),
            "dXXt": s.d(lambda t: t.X @ t.X.T, f) - comm(s.Phi, XXt)}


@claim("nu-action-rank", kind="dim", sizes=admissible(n_max=4, n_min=2, condition="n >= 2"))
def action_rank(s):
    """xi -> xi X on so(n) has rank dim V(n, r) = nr - r(r+1)/2."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "n"))
    return {"rank": Rank(M, n * r - r * (r + 1) // 2)}


@claim("nu-phi-moves", kind="not", expect="nonzero",
       sizes=admissible(n_max=4, where=lambda n, r: r < n, condition="r < n (XX^T = I at r = n)"))
def phi_not_conserved(s):
    """The momentum Phi is NOT conserved along the Neumann flow (dPhi/dt = [XX^T, A] != 0)."""
    return {"dPhi": s.d(lambda t: t.Phi, printed_No(s))}
