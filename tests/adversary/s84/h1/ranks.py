"""h1 (stop 84): malformed or boundary Rank / Count statements.  X is n×r with XᵀX = I_r, so rank X = r.

h1-rank-bool        Rank(X, True): a bool is not an int: `error` expected everywhere.
h1-rank-np          Rank(X, numpy.int64(r)) at fixed sizes (r from int(s.r)): a numpy int is not an int: `error`.
h1-rank-index       Rank(X, obj) with obj an object with __index__ (= r): `error` (not an int).
h1-rank-stmtint     Rank(X, obj) with obj of a class defining _statement_int (returns 1): the engine's own door
                    for sizes, used by a user class: TRUE only at r = 1; must not be `proved` at r ≥ 2.
h1-rank-huge        Rank(X, 10**40): FALSE (rank X = r): `fails` or `error`, never proved.
h1-rank-above       Rank(X, r + 1) (above min(n, r) = r): FALSE: `fails`.
h1-rank-r           Rank(X, r): TRUE (control).
h1-rank-zero-f      Rank(X, 0): FALSE (X ≠ 0).
h1-rank-zero-empty  Rank(0_{(n−r)×r}, 0) including r = n (an empty 0×r matrix): TRUE (rank 0).
h1-rank-everywhere  Rank(X, r, generic=False): TRUE at every point (XᵀX = I_r).
h1-rank-every-f     Rank(X, r − 1, generic=False) stated r ≥ 2: FALSE.
h1-rank-kernel-bad  Rank(X, r − 1, kernel=K) with K a generic n×r "kernel" (wrong number of rows where n ≠ r: X has r
                    columns; not a kernel at all): FALSE (rank X = r): never proved; `error` or `fails`.
h1-rank-kernel-zero Rank(X, r − 1, kernel=0_{r×1}): FALSE: a zero kernel certifies nothing: never proved.
h1-rank-kernel-fake Rank(Φ, ..) with a kernel K = X (Φ X ≠ 0 in general: Φ X = P − X Pᵀ X): the kernel is wrong and
                    the expected rank n − r is FALSE for r < n... rank Φ is generically 2r for 2r ≤ n (Φ = PXᵀ − XPᵀ,
                    rank ≤ 2r): stated at (3,1), (4,1): rank 2; expected 2 TRUE with a WRONG kernel (kernel must
                    never refute; verdict should still be proved or undecided, never fails).
h1-rank-kernel-f    the same wrong kernel with expected 1 (FALSE): never proved.
h1-rank-scalar      Rank(tr(PᵀP), 1): a scalar as the matrix: `error` or a right verdict (a nonzero 1×1: rank 1).
h1-rank-list        Rank([[1, 0], [0, 1]], 2): a Python list (no matrix of the scene): `error` or right (TRUE).
h1-count-bool       Count(True, 1): `error` (a bool is not an int).
h1-count-np         Count(numpy.int64(3), 3): `error`.
h1-count-neg        Count(−1, −1): an odd but consistent count: proved/checked or error; Count(−1, 1): never proved.
h1-count-neg-f      Count(−1, 1): FALSE.
h1-count-huge       Count(2**13001, 2**13001): `error` (too many digits).
h1-count-size       Count(n·r, n·r computed by hand at fixed sizes): TRUE; free: undecided.
h1-count-size-f     Count(n·r, n·r + 1): FALSE.
"""
import numpy as np

from stiefelsym import Count, Rank, admissible, claim

SZ = admissible(n_max=3, n_min=2)
R2 = admissible(n_max=3, n_min=2, r_min=2)
PHI = admissible(n_max=4, n_min=3, r_min=1, r_max=1)


class _Idx:
    def __init__(self, v):
        self.v = v

    def __index__(self):
        return self.v


class _StmtInt:
    def _statement_int(self, what):
        return 1


@claim("h1-rank-bool", kind="dim", sizes=SZ)
def rank_bool(s):
    return {"rank": Rank(s.X, True)}


@claim("h1-rank-np", kind="dim", sizes=SZ)
def rank_np(s):
    return {"rank": Rank(s.X, np.int64(int(s.r)))}


@claim("h1-rank-index", kind="dim", sizes=SZ)
def rank_index(s):
    return {"rank": Rank(s.X, _Idx(int(s.r)))}


@claim("h1-rank-stmtint", kind="dim", sizes=SZ)
def rank_stmtint(s):
    return {"rank": Rank(s.X, _StmtInt())}


@claim("h1-rank-huge", kind="dim", sizes=SZ)
def rank_huge(s):
    return {"rank": Rank(s.X, 10 ** 40)}


@claim("h1-rank-above", kind="dim", sizes=SZ)
def rank_above(s):
    return {"rank": Rank(s.X, s.r + 1)}


@claim("h1-rank-r", kind="dim", sizes=SZ)
def rank_r(s):
    return {"rank": Rank(s.X, s.r)}


@claim("h1-rank-zero-f", kind="dim", sizes=SZ)
def rank_zero_f(s):
    return {"rank": Rank(s.X, 0)}


@claim("h1-rank-zero-empty", kind="dim", sizes=SZ)
def rank_zero_empty(s):
    return {"rank": Rank(s.zeros(s.n - s.r, s.r, ("n-r", "r")), 0)}


@claim("h1-rank-everywhere", kind="dim", sizes=SZ)
def rank_everywhere(s):
    return {"rank": Rank(s.X, s.r, generic=False)}


@claim("h1-rank-every-f", kind="dim", sizes=R2)
def rank_every_f(s):
    return {"rank": Rank(s.X, int(s.r) - 1, generic=False)}


@claim("h1-rank-kernel-bad", kind="dim", sizes=R2)
def rank_kernel_bad(s):
    K = s.generic("Kb", "n", "r")
    return {"rank": Rank(s.X, int(s.r) - 1, kernel=K)}


@claim("h1-rank-kernel-zero", kind="dim", sizes=R2)
def rank_kernel_zero(s):
    return {"rank": Rank(s.X, int(s.r) - 1, kernel=s.zeros(s.r, 1, ("r", "?")))}


@claim("h1-rank-kernel-fake", kind="dim", sizes=PHI)
def rank_kernel_fake(s):
    return {"rank": Rank(s.Phi, 2, kernel=s.X)}


@claim("h1-rank-kernel-f", kind="dim", sizes=PHI)
def rank_kernel_f(s):
    return {"rank": Rank(s.Phi, 1, kernel=s.X)}


@claim("h1-rank-scalar", kind="dim", sizes=SZ)
def rank_scalar(s):
    return {"rank": Rank(s.tr(s.P.T @ s.P), 1)}


@claim("h1-rank-list", kind="dim", sizes=SZ)
def rank_list(s):
    return {"rank": Rank([[1, 0], [0, 1]], 2)}


@claim("h1-count-bool", kind="dim", sizes=SZ)
def count_bool(s):
    return {"c": Count(True, 1)}


@claim("h1-count-np", kind="dim", sizes=SZ)
def count_np(s):
    return {"c": Count(np.int64(3), 3)}


@claim("h1-count-neg", kind="dim", sizes=SZ)
def count_neg(s):
    return {"c": Count(-1, -1)}


@claim("h1-count-neg-f", kind="dim", sizes=SZ)
def count_neg_f(s):
    return {"c": Count(-1, 1)}


@claim("h1-count-huge", kind="dim", sizes=SZ)
def count_huge(s):
    return {"c": Count(2 ** 13001, 2 ** 13001)}


@claim("h1-count-size", kind="dim", sizes=SZ)
def count_size(s):
    return {"c": Count(s.n * s.r, int(s.n) * int(s.r))}


@claim("h1-count-size-f", kind="dim", sizes=SZ)
def count_size_f(s):
    return {"c": Count(s.n * s.r, int(s.n) * int(s.r) + 1)}
