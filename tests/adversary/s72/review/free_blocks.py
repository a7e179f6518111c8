"""s72 review: block matrices under the dimension-free method (attempts F1-F5)."""
from stiefelsym import admissible, block, claim

SIZES = admissible(n_max=3)


@claim("s72-free-two-splittings", paper="No", kind="id", section="t", sizes=SIZES)
def two_splittings(s):
    """[X, 0_n] times [0_(r×n); Xᵀ]: an ill-typed product (columns r+n against rows r+r): error is right."""
    B1 = block([[s.X, s.zeros(s.n, s.n, ("n", "n"))]])
    B2 = block([[s.zeros(s.r, s.n, ("r", "n"))], [s.X.T]])
    return {"B1 B2": B1 @ B2}


@claim("s72-free-split-mismatch", paper="No", kind="id", section="t", sizes=SIZES)
def split_mismatch(s):
    """[X, I_n] [I_n ; Xᵀ]ᵀ-like product with splits r+n against n+r: X + X = 2X, claimed X (false)."""
    B1 = block([[s.X, s.In]])                 # n x (r+n)
    B2 = block([[s.In], [s.X.T]])             # (n+r) x n
    return {"B1 B2 - X": B1 @ B2 - s.X @ s.X.T}


@claim("s72-free-block-trace", paper="No", kind="id", section="t", sizes=SIZES)
def block_trace(s):
    """tr [[XᵀX, 0],[0, XXᵀ]] = 2r (true)."""
    B = block([[s.X.T @ s.X, s.zeros(s.r, s.n, ("r", "n"))], [s.zeros(s.n, s.r, ("n", "r")), s.X @ s.X.T]])
    return {"tr B - 2r": s.tr(B) - 2 * s.tr(s.Ir)}


@claim("s72-free-block-trace-false", paper="No", kind="id", section="t", sizes=SIZES)
def block_trace_false(s):
    """tr [[XᵀX, 0],[0, I_n]] = 2r (false for r < n: r + n)."""
    B = block([[s.X.T @ s.X, s.zeros(s.r, s.n, ("r", "n"))], [s.zeros(s.n, s.r, ("n", "r")), s.In]])
    return {"tr B - 2r": s.tr(B) - 2 * s.tr(s.Ir)}


@claim("s72-free-block-transpose", paper="No", kind="id", section="t", sizes=SIZES)
def block_transpose(s):
    """[[0, X],[Xᵀ, 0]] is symmetric... claimed skew (false)."""
    B = block([[s.zeros(s.n, s.n, ("n", "n")), s.X], [s.X.T, s.zeros(s.r, s.r, ("r", "r"))]])
    return {"B + Bᵀ": B + B.T}
