# ruff: noqa
"""Claims on s.generic(name, "n-r", ...) blocks: true ones and false twins, at n = r (empty blocks), n = 2r
(R^(n-r) the size of R^r), and n > 2r.  Truth: truth.py (numpy).
Run: stiefelsym verify --claims nr_blocks.py --method exact --method modular --method rational --method float
     --method ball --method auto --size 2,1 --size 2,2 --size 3,3 --size 4,2 --size 5,2 --jobs 1 --no-report"""
from stiefelsym import admissible, block, claim

SIZES = admissible(n_max=5)


@claim("r2nr-gram-zero", kind="id", sizes=SIZES)
def gram_zero(s):
    """P₂ᵀP₂ = 0: false at n > r, true at n = r (P₂ has no rows)."""
    P2 = s.generic("P2", "n-r", "r")
    return {"P2tP2": P2.T @ P2}


@claim("r2nr-sym-true", kind="id", sizes=SIZES)
def sym_true(s):
    """S − Sᵀ = 0, K + Kᵀ = 0, tr K = 0 for generic symmetric S and skew K on R^(n-r) (true)."""
    S = s.generic("S", "n-r", "n-r", "sym")
    K = s.generic("K", "n-r", "n-r", "skew")
    return {"S": S - S.T, "K": K + K.T, "trK": s.tr(K)}


@claim("r2nr-trS-false", kind="id", sizes=SIZES)
def trs_false(s):
    """tr S = 0 for a generic symmetric S on R^(n-r): false at n > r, true at n = r (empty)."""
    return {"trS": s.tr(s.generic("S", "n-r", "n-r", "sym"))}


@claim("r2nr-half-psi-false", kind="id", sizes=admissible(n_max=4, where=lambda n, r: n == 2 * r))
def half_psi_false(s):
    """G + Ψ = 0 at n = 2r, G a generic (n − r) × r block (false)."""
    return {"G+Psi": s.generic("G", "n-r", "r") + s.Psi}


@claim("r2nr-half-psi-true", kind="id", sizes=admissible(n_max=4, where=lambda n, r: n == 2 * r))
def half_psi_true(s):
    """Ψ + Ψᵀ + (G − G) = 0 at n = 2r (true)."""
    G = s.generic("G", "n-r", "r")
    return {"x": s.Psi + s.Psi.T + (G - G)}


@claim("r2nr-chart-true", kind="id", sizes=admissible(n_max=5, where=lambda n, r: r < n))
def chart_true(s):
    """At X₀ = (I_r; 0), P₀ = (η; P₂) is tangent: X₀ᵀP₀ + P₀ᵀX₀ = 0, and X₀ᵀX₀ = I_r (true)."""
    P2 = s.generic("P2", "n-r", "r")
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    P0 = block([[s.eta], [P2]])
    return {"tan": X0.T @ P0 + P0.T @ X0, "orth": X0.T @ X0 - s.Ir}


@claim("r2nr-chart-false", kind="id", sizes=admissible(n_max=5, where=lambda n, r: r < n))
def chart_false(s):
    """P₀ᵀP₀ = ηᵀη (false at n > r: the P₂ᵀP₂ term)."""
    P2 = s.generic("P2", "n-r", "r")
    P0 = block([[s.eta], [P2]])
    return {"x": P0.T @ P0 - s.eta.T @ s.eta}


@claim("r2nr-with-a-false", kind="id", sizes=admissible(n_max=5, where=lambda n, r: r < n))
def with_a_false(s):
    """A block matrix B = diag(G, S) (G r×r generic, S (n−r)×(n−r) symmetric) commutes with A? false."""
    S = s.generic("S", "n-r", "n-r", "sym")
    G = s.generic("G", "r", "r")
    B = block([[G, s.zeros(s.r, s.n - s.r, ("r", "n-r"))], [s.zeros(s.n - s.r, s.r, ("n-r", "r")), S]])
    return {"[B,A]": B @ s.A - s.A @ B}


@claim("r2nr-with-a-true", kind="id", sizes=admissible(n_max=5, where=lambda n, r: r < n))
def with_a_true(s):
    """diag(c I_r, c I_(n−r)) A − A diag(c I_r, c I_(n−r)) = 0 (true: a multiple of I_n)."""
    c = s.scalar("c")
    B = block([[c * s.Ir, s.zeros(s.r, s.n - s.r, ("r", "n-r"))],
               [s.zeros(s.n - s.r, s.r, ("n-r", "r")), c * s.identity(s.n - s.r)]])
    return {"[B,A]": B @ s.A - s.A @ B}


@claim("r2nr-xblock-false", kind="id", sizes=admissible(n_max=5, where=lambda n, r: r < n))
def xblock_false(s):
    """Xᵀ (η; P₂) + (η; P₂)ᵀ X = 0 for every X (false: it holds at X₀ only)."""
    P0 = block([[s.eta], [s.generic("P2", "n-r", "r")]])
    return {"x": s.X.T @ P0 + P0.T @ s.X}
