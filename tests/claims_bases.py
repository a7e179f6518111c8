"""Claims written with stiefelsym.bases (tests/test_bases.py): ranks of linear maps between matrix spaces of the
paper, each with a false twin."""
from stiefelsym import Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, matrix_units, so_basis, sym_basis

SIZES = admissible(n_max=4, n_min=2, condition="n >= 2")


def _dim_v(n, r):
    return n * r - r * (r + 1) // 2


@claim("bases-action-rank", paper="hat", kind="dim", sizes=SIZES)
def action_rank(s):
    """(hat): SO(n) acts transitively on V(n, r), so xi -> xi X has rank dim V(n, r) on so(n)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "n")), _dim_v(n, r))}


@claim("bases-action-rank-plus-one", paper="hat", kind="dim", sizes=SIZES, expect="fails",
       erratum="a false twin: the rank of xi -> xi X is one more than dim V(n, r)")
def action_rank_plus_one(s):
    """A false twin of bases-action-rank."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "n")), _dim_v(n, r) + 1)}


@claim("bases-tangent-rank", paper="cond_X*", kind="dim", sizes=SIZES)
def tangent_rank(s):
    """The tangent space {V: XᵀV + VᵀX = 0} has dimension dim V(n, r): the map V -> XᵀV + VᵀX on n x r matrices
    has rank r(r+1)/2 (onto Sym(r))."""
    r = int(s.r)
    M = matrix_of(s, lambda v: s.X.T @ v + v.T @ s.X, matrix_units(s, "n", "r"), kind="sym")
    return {"rank": Rank(M, r * (r + 1) // 2)}


@claim("bases-sandwich-rank", kind="dim", sizes=SIZES)
def sandwich_rank(s):
    """y -> XᵀyX maps Sym(n) onto Sym(r)."""
    r = int(s.r)
    return {"rank": Rank(matrix_of(s, lambda y: s.X.T @ y @ s.X, sym_basis(s, "n"), kind="sym"), r * (r + 1) // 2)}


@claim("bases-ad-rank", kind="dim", sizes=SIZES)
def ad_rank(s):
    """ad_xi on so(n) at a generic xi has rank dim so(n) − rank so(n) = n(n − 1)/2 − ⌊n/2⌋."""
    n = int(s.n)
    return {"rank": Rank(matrix_of(s, lambda e: comm(s.xi, e), so_basis(s, "n"), kind="skew"),
                         n * (n - 1) // 2 - n // 2)}


@claim("bases-ad-rank-full", kind="dim", sizes=SIZES, expect="fails",
       erratum="a false twin: ad_xi is never onto so(n) for n >= 2 (its kernel holds xi)")
def ad_rank_full(s):
    """A false twin of bases-ad-rank."""
    n = int(s.n)
    return {"rank": Rank(matrix_of(s, lambda e: comm(s.xi, e), so_basis(s, "n"), kind="skew"), n * (n - 1) // 2)}


@claim("bases-zero-map-full-rank", kind="dim", sizes=SIZES, expect="fails",
       erratum="a false twin: the map is 0 (X^T xi X is skew), not of full rank")
def zero_map_full_rank(s):
    """A false statement of full rank: xi -> XᵀξX + (XᵀξX)ᵀ is the zero map on so(n)."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: s.X.T @ xi @ s.X + (s.X.T @ xi @ s.X).T, so_basis(s, "n"))
    return {"rank": Rank(M, n * (n - 1) // 2)}


@claim("bases-skew-image-in-sym-coordinates", kind="dim", sizes=SIZES, expect="fails",
       erratum="a false statement (own attempt): the image of xi -> X^T xi X is so(r), of dimension r(r-1)/2")
def skew_image_in_sym_coordinates(s):
    """A false statement written the careless way: the rank of ξ ↦ XᵀξX read in "sym" coordinates, claimed to be
    dim Sym(r) = r(r+1)/2.  Its image is so(r): the sym coordinates' diagonal vanishes and Mᵢⱼ − Mⱼᵢ = 2Mᵢⱼ, so
    the rank is r(r−1)/2 whatever the coordinates."""
    r = int(s.r)
    M = matrix_of(s, lambda xi: s.X.T @ xi @ s.X, so_basis(s, "n"), kind="sym")
    return {"rank": Rank(M, r * (r + 1) // 2)}
