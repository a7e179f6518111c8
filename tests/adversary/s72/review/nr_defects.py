"""s72 review: edge inputs of blocks on R^(n-r) looking for tracebacks or unclear messages (attempts X1-X8)."""
from stiefelsym import Rank, admissible, claim, det, elementary

ALL = admissible(n_max=3)


@claim("s72-x-skew-one", paper="No", kind="id", section="t", sizes=admissible(n_max=3, where=lambda n, r: n - r == 1))
def skew_one(s):
    """A generic skew (n−r)×(n−r) block at n − r = 1 is 0 (true)."""
    return {"K": s.generic("K", "n-r", "n-r", "skew")}


@claim("s72-x-identity-nr", paper="No", kind="id", section="t", sizes=ALL)
def identity_nr(s):
    """tr I_(n−r) + tr I_r − tr I_n = 0 with s.identity(s.n − s.r, "n-r") (true, at n = r too)."""
    return {"t": s.tr(s.identity(s.n - s.r, "n-r")) + s.tr(s.Ir) - s.tr(s.In)}


@claim("s72-x-det-empty", paper="No", kind="id", section="t", sizes=admissible(n_max=3, where=lambda n, r: r == n))
def det_empty(s):
    """det of the empty (n−r)×(n−r) block is 1 (true by convention)."""
    return {"d": det(s, s.generic("G", "n-r", "n-r")) - 1}


@claim("s72-x-rank-empty", paper="No", kind="dim", section="t", sizes=admissible(n_max=3, where=lambda n, r: r == n))
def rank_empty(s):
    """rank of the empty (n−r)×r block is 0 (true)."""
    return {"rk": Rank(s.generic("G", "n-r", "r"), 0)}


@claim("s72-x-elementary-nr", paper="No", kind="id", section="t", sizes=admissible(n_max=3, where=lambda n, r: n - r == 1))
def elementary_nr(s):
    """e_2 of a 1×1 block is 0 (true)."""
    return {"e2": elementary(s, s.generic("G", "n-r", "n-r"), 2)[2]}


@claim("s72-x-bad-space", paper="No", kind="id", section="t", sizes=ALL)
def bad_space(s):
    """s.generic with the space 'r-n' (refused with a message)."""
    return {"G": s.generic("G", "r-n", "r")}


@claim("s72-x-inverse-nr", paper="No", kind="id", section="t", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def inverse_nr(s):
    """G⁻¹G = I_(n−r) for a generic square block (true where G is invertible)."""
    G = s.generic("G", "n-r", "n-r")
    return {"x": G.inv() @ G - s.identity(s.n - s.r, "n-r")}


@claim("s72-x-sym-op-nr", paper="No", kind="id", section="t", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def sym_op_nr(s):
    """The operator letter applied to a skew (n−r)×(n−r) block (refused or an operator of its own)."""
    op = s.sym_operator()
    K = s.generic("K", "n-r", "n-r", "skew")
    return {"x": op(K) + op(K).T}
