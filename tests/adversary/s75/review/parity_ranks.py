"""Generic ranks of skew matrices whose truth depends on the parity of n.  Docstrings state the truth:
rank Ψ (r x r skew, generic) = r if r even, r − 1 if r odd; rank Φ = min(2r, n) rounded down to even."""
from stiefelsym import admissible, claim, Rank

SZ = admissible(n_max=5, n_min=2)


@claim("s75-rank-psi-full", kind="dim", sizes=SZ)
def rank_psi_full(s):
    """rank Ψ = r (generic): TRUE for r even, FALSE for r odd."""
    return {"rank": Rank(s.Psi, int(s.r))}


@claim("s75-rank-phi-naive", kind="dim", sizes=SZ)
def rank_phi_naive(s):
    """rank Φ = min(2r, n) (generic): TRUE for 2r <= n or n even; FALSE when n odd and 2r > n
    (a skew matrix has even rank), and at r = ... (2r = n+1)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(s.Phi, min(2 * r, n))}


@claim("s75-rank-phi-true", kind="dim", sizes=SZ)
def rank_phi_true(s):
    """rank Φ = min(2r, n − n mod 2) except at r = 1, n = ... : TRUE (rank of PXᵀ − XPᵀ is 2·min(r, ⌊n/2⌋)),
    but at r = n the momentum P = XΨ gives Φ = XΨXᵀ of rank Ψ = r − r mod 2."""
    n, r = int(s.n), int(s.r)
    k = min(2 * r, n - n % 2)
    return {"rank": Rank(s.Phi, k)}


@claim("s75-rank-phi-every-point", kind="dim", sizes=SZ)
def rank_phi_every_point(s):
    """rank Φ = min(2r, n − n mod 2) at EVERY point: FALSE (Φ = 0 at P = 0)."""
    n, r = int(s.n), int(s.r)
    k = min(2 * r, n - n % 2)
    return {"rank": Rank(s.Phi, k, generic=False)}
