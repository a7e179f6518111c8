"""A new user's deliberately false statements (each must be refuted with a witness).

Run:  stiefelsym verify --claims tests/adversary/s74/newuser/false_claims.py --jobs 1 --max-n 3
"""
from stiefelsym import Rank, admissible, claim, comm

from nu_helpers import printed_No


@claim("nu-false-LA-sign", paper="LA1", kind="lax", sizes=admissible(n_max=3))
def lax_wrong_sign(s):
    """FALSE: the Lax partner with +lambda A in place of -lambda A."""
    lam = s.lam
    L = lambda t: lam * t.Phi + t.X @ t.X.T - lam * lam * t.A
    return {"LA1": s.d(L, printed_No(s)) - comm(s.Phi + lam * s.A, L(s))}


@claim("nu-false-rank", kind="dim", sizes=admissible(n_max=3))
def wrong_rank(s):
    """FALSE: X has rank r + 1."""
    return {"rank": Rank(s.X, int(s.r) + 1)}


@claim("nu-false-not", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def psi_moves(s):
    """FALSE: Psi is not conserved along (No) (it is conserved)."""
    return {"dPsi": s.d(lambda t: t.Psi, printed_No(s))}


@claim("nu-erratum-LA-sign", paper="LA1", kind="lax", sizes=admissible(n_max=3),
       fails_at=lambda n, r: n >= 2, erratum="the Lax partner printed with +lambda A; it is Phi - lambda A")
def lax_wrong_sign_declared(s):
    """A known misprint, declared: +lambda A in the Lax partner (holds only at n = 1, where everything commutes)."""
    lam = s.lam
    L = lambda t: lam * t.Phi + t.X @ t.X.T - lam * lam * t.A
    return {"LA1": s.d(L, printed_No(s)) - comm(s.Phi + lam * s.A, L(s))}
