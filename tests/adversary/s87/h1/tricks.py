"""s87h1 tricks: FALSE statements (except where noted) that try to come out proved/checked.

 s87h1k-gram-psi-square (FALSE for r < n, TRUE at r = n): PᵀP = −Ψ²/4 claimed for every size
   (at r = n, P = XW, Ψ = 2W, PᵀP = −W²).
 s87h1k-xptx-zero (FALSE for r ≥ 2, TRUE at r = 1 where PᵀX = 0): XPᵀX = 0 for every size.
 s87h1k-xxt-identity (FALSE for r < n, TRUE at r = n): XXᵀ = I_n for every size.
 s87h1k-rank-every-point (FALSE for r ≥ 3: at Ψ = 0 the rank drops to 2r(n−r) < 2l): the map of Lemma LEMA1
   has rank 2l at EVERY point of T*V (generic=False).
 s87h1k-xtax-offdiag (FALSE, r ≥ 2): (XᵀAX)₁₂ = 0 — true at X = X₀ = (E₁..E_r) with diagonal A, a chart trap.
 s87h1k-not-constraint (FALSE as a 'nonzero' statement: XᵀX − I and XᵀP + PᵀX vanish on T*V): kind="not".
 s87h1k-inverse-r1 (FALSE for r ≥ 2, TRUE at r = 1 where K = XᵀP = 0): a ↦ a + Ka − aK on Sym(r) is its own
   inverse... stated as Inverse(op, identity).  op(a) = a + Ka − aK is symmetric (K skew), invertible, but its
   inverse is not the identity unless K = 0.
 s87h1k-phi-conserved-neumann (FALSE, true only for A ∝ I): Φ is conserved by (NE_XP).
 s87h1k-ad-a-rank-everywhere (TRUE for generic distinct a_i; FALSE for some A): ξ ↦ [ξ, A] on so(n) has rank
   n(n−1)/2 at every point (generic=False) — A is a parameter, not a point of T*V (probe of the meaning).
"""
from __future__ import annotations

from stiefelsym import Inverse, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, matrix_units, so_basis

ANY = admissible(n_max=4)


@claim("s87h1k-gram-psi-square", kind="id", section="4", sizes=ANY)
def gram_psi_square(s):
    """PᵀP = −Ψ²/4 (FALSE for r < n)."""
    return {"PtP + Psi^2/4": s.P.T @ s.P + s.Psi @ s.Psi / 4}


@claim("s87h1k-xptx-zero", kind="id", section="7", sizes=ANY)
def xptx_zero(s):
    """XPᵀX = 0 (FALSE for r ≥ 2)."""
    return {"XPtX": s.X @ s.P.T @ s.X}


@claim("s87h1k-xxt-identity", kind="id", section="7", sizes=ANY)
def xxt_identity(s):
    """XXᵀ = I (FALSE for r < n)."""
    return {"XXt - I": s.X @ s.X.T - s.In}


def lambda1_matrix(s, P):
    h, v = P @ s.X.T - s.X @ P.T, s.X @ s.X.T
    return matrix_of(s, lambda u: comm(v, u) + comm(h, (u - u.T) / 2), matrix_units(s, "n", "n"))


@claim("s87h1k-rank-every-point", kind="dim", section="6", sizes=ANY)
def rank_every_point(s):
    """rank 2l at every point (FALSE for r ≥ 3)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(lambda1_matrix(s, s.P), 2 * r * (n - r) + r * (r - 1) // 2 - r // 2, generic=False)}


@claim("s87h1k-xtax-offdiag", kind="id", section="6", sizes=admissible(n_max=4, r_min=2))
def xtax_offdiag(s):
    """(XᵀAX)₁₂ = 0 (FALSE)."""
    return {"(XtAX)_12": (s.X.T @ s.A @ s.X)[0, 1]}


@claim("s87h1k-not-constraint", kind="not", expect="nonzero", section="1", sizes=ANY)
def not_constraint(s):
    """'XᵀX − I and XᵀP + PᵀX do not vanish' (FALSE)."""
    return {"XtX - I": s.X.T @ s.X - s.Ir, "XtP + PtX": s.X.T @ s.P + s.P.T @ s.X}


def _op(t, a):
    K = t.X.T @ t.P
    return (a + K @ a - a @ K,)


def _id(t, a):
    return (a,)


@claim("s87h1k-inverse-r1", kind="id", section="6", sizes=ANY)
def inverse_r1(s):
    """a ↦ a + Ka − aK has inverse the identity (FALSE for r ≥ 2)."""
    return {"inverse": Inverse(_op, _id, on=("Sym(r)",))}


def H_NE(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s87h1k-phi-conserved-neumann", kind="id", section="7", sizes=ANY)
def phi_conserved(s):
    """Φ conserved by (NE_XP) (FALSE unless A ∝ I)."""
    return {"dPhi": s.d(lambda t: t.Phi, s.dirac_flow(H_NE))}


@claim("s87h1k-ad-a-rank-everywhere", kind="dim", section="4", sizes=admissible(n_max=4, n_min=2))
def ad_a_rank(s):
    """ξ ↦ [ξ, A] has rank n(n−1)/2 on so(n) at every point (probe)."""
    n = int(s.n)
    return {"rank": Rank(matrix_of(s, lambda xi: comm(xi, s.A), so_basis(s, "n")), n * (n - 1) // 2, generic=False)}
