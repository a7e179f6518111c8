"""Claims on families (r_in, r_is_n), corrections proved for every n, r, small symbolic budgets (exact_max_n = 2):
beyond n = 2 the exact method is the dimension-free proof specialised."""
from stiefelsym import admissible, claim


@claim("h2-f5-r1n", kind="id", sizes=admissible(n_max=7, r_in=(1, "n")), statement="X^T P = 0 at r = 1 or r = n?",
       exact_max_n=2)
def r1n(s):
    """XᵀP = 0: true at r = 1, false at r = n >= 2"""
    return {"r": s.X.T @ s.P}


@claim("h2-f5-r1n-true", kind="id", sizes=admissible(n_max=7, r_in=(1, "n")),
       statement="XX^T P X^T ... true at r = 1 and r = n", exact_max_n=2)
def r1n_true(s):
    """XᵀP + PᵀX = 0 and (XXᵀ)X = X"""
    return {"r": s.X.T @ s.P + s.P.T @ s.X, "q": s.X @ s.X.T @ s.X - s.X}


@claim("h2-f5-r2", kind="id", sizes=admissible(n_max=7, r_in=(2,)), statement="r = 2: X^T P = -P^T X",
       exact_max_n=2)
def r2(s):
    """true at r = 2"""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("h2-f5-r2-false", kind="id", sizes=admissible(n_max=7, r_in=(2,)), statement="r = 2: X^T P = 0",
       exact_max_n=2)
def r2f(s):
    """false at r = 2"""
    return {"r": s.X.T @ s.P}


@claim("h2-f5-sq", kind="id", sizes=admissible(n_max=7, r_is_n=True), statement="PX^T + XP^T = 0 at r = n",
       exact_max_n=2)
def sq(s):
    """true at r = n: P = XΩ with Ω skew, PXᵀ = XΩXᵀ skew"""
    return {"r": s.P @ s.X.T + s.X @ s.P.T}


@claim("h2-f5-sq-gen", kind="id", sizes=admissible(n_max=7), statement="PX^T + XP^T = 0",
       exact_max_n=2)
def sq_gen(s):
    """false at r < n (true at r = n)"""
    return {"r": s.P @ s.X.T + s.X @ s.P.T}


@sq_gen.claim.correction("projected: XX^T(PX^T + XP^T)XX^T = 0")
def sq_gen_fix(s):
    Q = s.X @ s.X.T
    return {"r": Q @ (s.P @ s.X.T + s.X @ s.P.T) @ Q}


@sq_gen.claim.correction("a wrong projection: (PX^T + XP^T)XX^T = 0")
def sq_gen_wrong(s):
    Q = s.X @ s.X.T
    return {"r": (s.P @ s.X.T + s.X @ s.P.T) @ Q}
