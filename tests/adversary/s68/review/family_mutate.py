# ruff: noqa
"""Claims stated on families of sizes (r = 1, r = 2, r = n, unions), true there and false elsewhere, for
`verify --method free` and `mutate` (mutants on the families' graphs against the graphs at sizes)."""
from stiefelsym import Count, admissible, claim, comm, twisted


@claim("fm-r1n", kind="id", sizes=admissible(n_max=4, r_in=(1, "n")))
def fm_r1n(s):
    """At r = 1 and r = n: X^T P = P^T X... no: X^T P P^T X = P^T X X^T P at r = 1; at r = n, P X^T + X P^T = 0."""
    X, P = s.X, s.P
    return {"PXt+XPt times XtP": (P @ X.T + X @ P.T) @ X @ (X.T @ P)}


@claim("fm-r1-scalar", kind="id", sizes=admissible(n_max=4, r_in=(1,)))
def fm_r1_scalar(s):
    """At r = 1: X^T A X P^T P = P^T P X^T A X (1x1 commute); and X^T P = 0."""
    X, P, A = s.X, s.P, s.A
    return {"comm": X.T @ A @ X @ P.T @ P - P.T @ P @ X.T @ A @ X, "XtP": X.T @ P}


@claim("fm-r2-cayley", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def fm_r2_cayley(s):
    """At r = 2: Cayley-Hamilton for M = X^T A X: M^2 - tr(M) M + det(M) I = 0, det M = (tr(M)^2 - tr(M^2))/2."""
    X, A = s.X, s.A
    M = X.T @ A @ X
    t1, t2 = s.tr(M), s.tr(M @ M)
    return {"CH": M @ M - t1 * M + ((t1 * t1 - t2) * s.q(1, 2)) * s.Ir}


@claim("fm-r2-skew", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def fm_r2_skew(s):
    """At r = 2 two skew matrices commute: [X^T P, X^T A P - P^T A X] = 0."""
    X, P, A = s.X, s.P, s.A
    W = X.T @ P
    V = X.T @ A @ P - P.T @ A @ X
    return {"[W,V]": comm(W, V)}


@claim("fm-n-count", kind="dim", sizes=admissible(n_max=4, r_in=(2,)))
def fm_n_count(s):
    """A count of r: 3r = 6 at r = 2."""
    return {"3r": Count(s.r * 3, 6, meaning="three times r")}
