"""Rank claims whose symbolic chart is beyond budget (a 4x4 or larger symbolic inverse), for the new
_full_ranks_at_points path of the exact method."""
from stiefelsym import Count, Rank, admissible, claim

SQ = admissible(n_max=5, n_min=4, where=lambda n, r: r == n, condition="r = n")
BIG = admissible(n_max=6, n_min=4, where=lambda n, r: r >= 4, condition="r >= 4")


def big_inv(s):
    return (s.Ir + s.P.T @ s.P).inv()


def det_entries(M, m):
    """Leibniz determinant of an m x m matrix from its entries (scalars)."""
    from itertools import permutations
    tot = None
    for p in permutations(range(m)):
        sign = 1
        for i in range(m):
            for j in range(i + 1, m):
                if p[i] > p[j]:
                    sign = -sign
        term = None
        for i in range(m):
            term = M[i, p[i]] if term is None else term * M[i, p[i]]
        term = term if sign == 1 else -term
        tot = term if tot is None else tot + term
    return tot


@claim("br-true-full", kind="dim", sizes=BIG)
def true_full(s):
    """TRUE: (I + P^T P)^{-1} has rank r."""
    return {"rank": Rank(big_inv(s), int(s.r))}


@claim("br-one-component", kind="dim", sizes=SQ)
def one_component(s):
    """FALSE on component det X = 1: diag(det X - 1, tr (I+P^TP)^{-1}) has generic rank 2."""
    n = int(s.n)
    d = det_entries(s.X, n)
    t = s.tr(big_inv(s))
    z = s.q(0)
    return {"rank": Rank(s.mat([[d - s.q(1), z], [z, t]]), 2)}


@claim("br-one-component-b", kind="dim", sizes=SQ)
def one_component_b(s):
    """FALSE on component det X = -1: diag(det X + 1, tr) has generic rank 2."""
    n = int(s.n)
    d = det_entries(s.X, n)
    t = s.tr(big_inv(s))
    z = s.q(0)
    return {"rank": Rank(s.mat([[d + s.q(1), z], [z, t]]), 2)}


@claim("br-every-point", kind="dim", sizes=BIG)
def every_point(s):
    """FALSE at every point: [X00 * tr(inv)] rank 1 at every point (X00 vanishes somewhere)."""
    return {"rank": Rank(s.mat([[s.X[0, 0] * s.tr(big_inv(s))]]), 1, generic=False)}


@claim("br-every-point-true", kind="dim", sizes=BIG)
def every_point_true(s):
    """TRUE at every point: (I + P^TP)^{-1} invertible everywhere."""
    return {"rank": Rank(big_inv(s), int(s.r), generic=False)}


@claim("br-full-plus-false-residual", kind="id", sizes=BIG)
def full_plus_false(s):
    """FALSE: a full rank and a false residual tr(P^T P) = 0 ."""
    return {"rank": Rank(big_inv(s), int(s.r)), "res": s.tr(s.P.T @ s.P)}


@claim("br-full-plus-true-residual", kind="id", sizes=BIG)
def full_plus_true(s):
    """TRUE: a full rank and X^T X = I."""
    return {"rank": Rank(big_inv(s), int(s.r)), "res": s.X.T @ s.X - s.Ir}


@claim("br-full-plus-false-count", kind="dim", sizes=BIG)
def full_plus_false_count(s):
    """FALSE: a full rank and a count 1 = 2."""
    return {"rank": Rank(big_inv(s), int(s.r)), "c": Count(1, 2)}


@claim("br-psi-rank-odd", kind="dim", sizes=SQ)
def psi_rank_odd(s):
    """FALSE for odd r: Psi (skew) times inv has full rank r."""
    return {"rank": Rank(s.Psi @ big_inv(s), int(s.r))}


@claim("br-kernel-full", kind="dim", sizes=BIG)
def kernel_full(s):
    """FALSE: rank r with a kernel certificate claiming X^T P ... rank r-1 is printed as r."""
    M = s.Psi @ big_inv(s)
    return {"rank": Rank(M, int(s.r))}
