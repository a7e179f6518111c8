"""Claims whose graph needs r as a number (int(s.r)), free_max_r = 3: a proof per family r = k."""
from stiefelsym import admissible, claim


@claim("h2-pr-true", kind="id", sizes=admissible(n_max=6), statement="sum_k X^T P + P^T X = 0", free_max_r=3,
       exact_max_n=4)
def pr_true(s):
    """true: r copies of the constraint"""
    k = int(s.r)
    out = s.X.T @ s.P + s.P.T @ s.X
    acc = out
    for _ in range(k - 1):
        acc = acc + out
    return {"r": acc}


@claim("h2-pr-r1", kind="id", sizes=admissible(n_max=6), statement="X^T P = 0 (true at r = 1 only)", free_max_r=3,
       exact_max_n=4)
def pr_r1(s):
    """XᵀP with a loop of r terms (true at r = 1 only)"""
    k = int(s.r)
    acc = s.X.T @ s.P
    for _ in range(k - 1):
        acc = acc + 0 * s.X.T @ s.P
    return {"r": acc}


@claim("h2-pr-r2", kind="id", sizes=admissible(n_max=6), statement="r-dependent: true at r = 2 only", free_max_r=3,
       exact_max_n=4)
def pr_r2(s):
    """at r = 2: tr(Psi^2) - ... ; the graph is (r-2) * X^T X + (X^T P + P^T X)"""
    k = int(s.r)
    return {"r": (k - 2) * (s.X.T @ s.X) + s.X.T @ s.P + s.P.T @ s.X}


@claim("h2-pr-r3", kind="id", sizes=admissible(n_max=6, r_min=2), statement="det-like at r = 3 only", free_max_r=3,
       exact_max_n=4)
def pr_r3(s):
    """(r - 3)^2 * (X^T X) : true at r = 3 only"""
    k = int(s.r)
    return {"r": ((k - 3) ** 2) * (s.X.T @ s.X)}
