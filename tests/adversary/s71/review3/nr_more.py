# ruff: noqa
"""s.generic(name, "n-r", ...) blocks: statements whose truth depends on r at a fixed n through the block's size
alone (sharing across r would be wrong), an identity on R^(n-r) written through s.identity(s.n - s.r), and
the block compared with a block of X at X0 (X itself is not at X0).  Truth: truth.py.
Run: stiefelsym verify --claims nr_more.py --size 4,1 --size 4,2 --size 4,3 --method auto --method modular
     --method exact --method float --jobs 1 --no-report"""
from stiefelsym import Count, Rank, admissible, block, claim

SIZES = admissible(n_max=4, where=lambda n, r: r < n)


@claim("r3-nr-rank3", kind="dim", sizes=SIZES)
def nr_rank3(s):
    """rank S = 3 for a generic symmetric S on R^(n-r): true only at n − r = 3 ((4,1) here)."""
    return {"rk": Rank(s.generic("S", "n-r", "n-r", "sym"), 3)}


@claim("r3-nr-trace-id", kind="id", sizes=SIZES)
def nr_trace_id(s):
    """tr I_(n−r) − 2 = 0: true only at n − r = 2 ((4,2) here)."""
    return {"t": s.tr(s.identity(s.n - s.r)) - 2}


@claim("r3-nr-gram-id", kind="id", sizes=SIZES)
def nr_gram_id(s):
    """G Gᵀ G − G = 0 for a generic (n − r) × r block G: false at every size."""
    G = s.generic("G", "n-r", "r")
    return {"x": G @ G.T @ G - G}


@claim("r3-nr-x-bottom", kind="id", sizes=SIZES)
def nr_x_bottom(s):
    """The bottom (n − r) × r block of X is 0 (false: X is a generic point of V, not X0)."""
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    return {"x": s.X - X0}


@claim("r3-nr-eta-block", kind="id", sizes=SIZES)
def nr_eta_block(s):
    """Xᵀ·(η; G) + (η; G)ᵀ·X = 0 with G a generic (n−r)×r block, at X = X0 written out (true)."""
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    P0 = block([[s.eta], [s.generic("G", "n-r", "r")]])
    return {"x": X0.T @ P0 + P0.T @ X0}
