"""Sizes times ints in shapes, blocks and numbers; true (t) and false (f) statements.  Truth: numpy_sizes.py."""
from stiefelsym import Count, Rank, admissible, block, claim

ALL = admissible(n_max=4)


@claim("sz-t-2n-identity", kind="id", sizes=ALL)
def t_2n_identity(s):
    """tr I_{2n} = 2 tr I_n (true)."""
    return {"r": s.tr(s.identity(s.n * 2, "n+n")) - 2 * s.tr(s.In)}


@claim("sz-f-2r-vs-n-plus-r", kind="id", sizes=ALL)
def f_2r(s):
    """tr I_{2r} = tr I_n + tr I_r (false for r < n)."""
    return {"r": s.tr(s.identity(s.r * 2, "r+r")) - s.tr(s.In) - s.tr(s.Ir)}


@claim("sz-t-block-stack", kind="id", sizes=ALL)
def t_block(s):
    """[X; X]ᵀ[X; X] = 2 I_r (true)."""
    B = block([[s.X], [s.X]])
    return {"r": B.T @ B - 2 * s.Ir}


@claim("sz-f-block-stack", kind="id", sizes=ALL)
def f_block(s):
    """[X; P]ᵀ[X; P] = 2 I_r (false)."""
    B = block([[s.X], [s.P]])
    return {"r": B.T @ B - 2 * s.Ir}


@claim("sz-t-zeros-2r", kind="id", sizes=ALL)
def t_zeros(s):
    """zeros(2r, r) equals [0; 0] times X^T X (true)."""
    Z = s.zeros(s.r * 2, s.r, ("r+r", "r"))
    return {"r": Z - block([[s.zeros(s.r, s.r, ("r", "r"))], [0 * s.Ir]]) @ (s.X.T @ s.X)}


@claim("sz-t-2n-number", kind="id", sizes=ALL)
def t_2n_number(s):
    """(2n) X − 2 tr(I_n) X = 0 with the size as a number (true)."""
    return {"r": s.X * (s.n * 2) - s.X * (2 * s.tr(s.In))}


@claim("sz-f-2n-number", kind="id", sizes=ALL)
def f_2n_number(s):
    """(2n) X − tr(I_n) X − tr(I_r) X = 0 (false for r < n)."""
    return {"r": s.X * (s.n * 2) - s.X * (s.tr(s.In) + s.tr(s.Ir))}


@claim("sz-t-rank-2r", kind="dim", sizes=ALL)
def t_rank(s):
    """[X; P]... the 2n x r block [X; X] has rank r; Count of its rows 2n (true)."""
    B = block([[s.X], [s.X]])
    return {"rank": Rank(B, s.r * 1), "rows": Count(B.shape[0], s.n * 2)}


@claim("sz-f-rank-2r", kind="dim", sizes=ALL)
def f_rank(s):
    """The 2n x 2r block diag(X, X) has rank r (false: 2r)."""
    B = block([[s.X, s.zeros(s.n, s.r, ("n", "r"))], [s.zeros(s.n, s.r, ("n", "r")), s.X]])
    return {"rank": Rank(B, s.r * 1)}


@claim("sz-f-count-0n", kind="dim", sizes=ALL)
def f_count(s):
    """Count n*0 = 0 is true; n*(-1) = -n against n (false)."""
    return {"zero": Count(s.n * 0, 0), "neg": Count(s.n * -1, s.n * 1)}
