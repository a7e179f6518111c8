"""Sizes as numbers (Dim * 0, negative, bool, Dim) and stiefelsym.bases edge cases."""
from stiefelsym import Count, Rank, admissible, claim
from stiefelsym.bases import matrix_of, matrix_units, so_basis

S = admissible(n_max=4, n_min=1)


@claim("d-zero-true", kind="id", sizes=S)
def d_zero_true(s):
    """TRUE: X * (n*0) = 0."""
    return {"r": s.X * (s.n * 0)}


@claim("d-neg-true", kind="id", sizes=S)
def d_neg_true(s):
    """TRUE: X*(n*-2) + X*(2 tr I_n) = 0."""
    return {"r": s.X * (s.n * -2) + s.X * (s.tr(s.In) * 2)}


@claim("d-neg-false", kind="id", sizes=S)
def d_neg_false(s):
    """FALSE: X*(n*-2) + X*tr(I_n) = 0."""
    return {"r": s.X * (s.n * -2) + s.X * s.tr(s.In)}


@claim("d-rmul-zero-false", kind="id", sizes=S)
def d_rmul_zero_false(s):
    """FALSE: X*(0*n) + X = 0."""
    return {"r": s.X * (0 * s.n) + s.X}


@claim("d-bool", kind="id", sizes=S)
def d_bool(s):
    """TRUE: X*(n*True) - X*tr(I_n) = 0."""
    return {"r": s.X * (s.n * True) - s.X * s.tr(s.In)}


@claim("d-count-neg", kind="dim", sizes=S)
def d_count_neg(s):
    """FALSE: -n = -(n+1) as a count."""
    return {"c": Count(s.n * -1, -(int(s.n) + 1))}


@claim("d-count-neg-true", kind="dim", sizes=S)
def d_count_neg_true(s):
    """TRUE: n * -1 = -n."""
    return {"c": Count(s.n * -1, -int(s.n))}


@claim("d-float", kind="id", sizes=S)
def d_float(s):
    """FALSE: X*(n*0.5) - X*n/2 + X = 0 (a float)."""
    return {"r": s.X * (s.n * 0.5) - s.X * s.tr(s.In) / 2 + s.X}


SZ = admissible(n_max=4, n_min=2)


@claim("b-sym-on-general-false", kind="dim", sizes=SZ)
def b_sym_on_general(s):
    """FALSE: V -> X^T V on n x r matrices has rank r(r+1)/2 (true rank r^2); coordinates taken as 'sym'."""
    r = int(s.r)
    M = matrix_of(s, lambda v: s.X.T @ v, matrix_units(s, "n", "r"), kind="sym")
    return {"rank": Rank(M, r * (r + 1) // 2)}


@claim("b-nonlinear", kind="dim", sizes=SZ)
def b_nonlinear(s):
    """A non-linear 'map' xi -> xi X + X (affine): rank of the vectors f(basis)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda xi: xi @ s.X + s.X, so_basis(s, "n"))
    return {"rank": Rank(M, min(n * (n - 1) // 2, n * r))}


@claim("b-so1", kind="dim", sizes=admissible(n_max=2, n_min=1))
def b_so1(s):
    """so(r) basis at r = 1: empty."""
    M = matrix_of(s, lambda z: s.X @ z, so_basis(s, "r"))
    return {"rank": Rank(M, 0)}


@claim("b-so-r-as-n", kind="dim", sizes=admissible(n_max=3, n_min=2, where=lambda n, r: r == n))
def b_so_r_as_n(s):
    """xi X with xi from so_basis(s, 'r') at r = n: typed on r, used on the left of X (n-side)."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "r"))
    return {"rank": Rank(M, n * (n - 1) // 2)}
