# ruff: noqa
"""Claims run alone (a short plan) and among many (a long plan, >= 16 runs): verdicts must agree."""
import os
from stiefelsym import Rank, Count, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

SZ = admissible(n_max=4, n_min=2)


@claim("sl-rank-high", paper="r65", kind="dim", sizes=SZ)
def rank_high(s):
    """ξ ↦ [ξ, XXᵀ] printed one too high (a false rank: the exact method computes kernel vectors)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: comm(xi, s.X @ s.X.T), so_basis(s, "n"))
    return {"rank": Rank(M, r * (n - r) + 1)}


@claim("sl-rank-true", paper="r65", kind="dim", sizes=SZ)
def rank_true(s):
    """ξ ↦ [ξ, XXᵀ] has rank r(n − r)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: comm(xi, s.X @ s.X.T), so_basis(s, "n"))
    return {"rank": Rank(M, r * (n - r))}


@claim("sl-rank-action", paper="r65", kind="dim", sizes=SZ)
def rank_action(s):
    """ξ ↦ ξX has rank nr − r(r+1)/2."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "n"))
    return {"rank": Rank(M, n * r - r * (r + 1) // 2)}


@claim("sl-rank-action-low", paper="r65", kind="dim", sizes=SZ)
def rank_action_low(s):
    """ξ ↦ ξX printed one too low."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "n"))
    return {"rank": Rank(M, n * r - r * (r + 1) // 2 - 1)}


@claim("sl-id-true", paper="r65", kind="id", sizes=SZ)
def id_true(s):
    """XXᵀX = X."""
    return {"r": s.X @ s.X.T @ s.X - s.X}


@claim("sl-id-false", paper="r65", kind="id", sizes=SZ)
def id_false(s):
    """XXᵀP = P (false for r < n)."""
    return {"r": s.X @ s.X.T @ s.P - s.P}


@claim("sl-psi", paper="r65", kind="id", sizes=SZ)
def psi(s):
    """XᵀP + PᵀX = 0 on T*V."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("sl-not", paper="r65", kind="not", expect="nonzero", sizes=SZ)
def not_claim(s):
    """XᵀAX ≠ A-ish: tr(XᵀAX) − tr(A) does not vanish (r < n)."""
    return {"r": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A)}


@claim("sl-count", paper="r65", kind="dim", sizes=SZ)
def count(s):
    """dim so(n) = n(n−1)/2."""
    n = int(s.n)
    return {"c": Count(len(so_basis(s, "n")), n * (n - 1) // 2)}


@claim("sl-count-false", paper="r65", kind="dim", sizes=SZ)
def count_false(s):
    """dim so(n) = n(n+1)/2 (false)."""
    n = int(s.n)
    return {"c": Count(len(so_basis(s, "n")), n * (n + 1) // 2)}


@claim("sl-rank-every", paper="r65", kind="dim", sizes=SZ)
def rank_every(s):
    """X has rank r at every point."""
    return {"rank": Rank(s.X, int(s.r), generic=False)}


@claim("sl-rank-psi", paper="r65", kind="dim", sizes=SZ)
def rank_psi(s):
    """Ψ has generic rank 2⌊r/2⌋."""
    r = int(s.r)
    return {"rank": Rank(s.Psi, 2 * (r // 2))}


@claim("sl-rank-psi-high", paper="r65", kind="dim", sizes=SZ)
def rank_psi_high(s):
    """Ψ printed of full rank r (false at odd r)."""
    r = int(s.r)
    return {"rank": Rank(s.Psi, r)}


@claim("sl-rank-phi", paper="r65", kind="dim", sizes=SZ)
def rank_phi(s):
    """Φ = PXᵀ − XPᵀ has generic rank 2 min(r, ⌊n/2⌋)... printed as 2r (false when 2r > n)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(s.Phi, min(2 * r, n - (n % 2)))}


def _pad(i):
    @claim(f"sl-pad-{i}", paper="r65", kind="id", sizes=SZ)
    def pad(s):
        """A padding claim: XᵀX = I_r."""
        return {"r": s.X.T @ s.X - s.Ir}
    return pad


for _i in range(6):
    _pad(_i)
