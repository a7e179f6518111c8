"""Adversary (generic kinds): one name at two shapes in the free scene (n x r and r x n; n x n sym and r x r sym
used with typed letters)."""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-gen-nr-vs-rn", paper="adv", kind="id", sizes=S)
def gen_nr_vs_rn(s):
    """False: tr(G Gᵀ) = tr(Hᵀ H) for G generic n×r and H generic r×n of the same name."""
    G, H = s.generic("G", "n", "r"), s.generic("G", "r", "n")
    return {"tr GGt - tr HtH": (G @ G.T).trace() - (H.T @ H).trace()}


@claim("adv-gk-sym-r-then-n", paper="adv", kind="id", sizes=S)
def sym_r_then_n(s):
    """False: tr(Xᵀ X S_r) = tr(S_n) (r x r one first, so the free letter is typed r; XᵀX = I_r)."""
    B = s.generic("S", "r", "r", "sym")
    A = s.generic("S", "n", "n", "sym")
    return {"tr(XtX S_r) - tr(S_n)": (s.X.T @ s.X @ B).trace() - A.trace()}


@claim("adv-gk-sym-square", paper="adv", kind="id", sizes=S)
def sym_square(s):
    """False: tr(S_n^2) = tr(S_r^2) + (tr S_n - tr S_r)^2 (two generic symmetric matrices of one name)."""
    A, B = s.generic("S", "n", "n", "sym"), s.generic("S", "r", "r", "sym")
    d = A.trace() - B.trace()
    return {"x": (A @ A).trace() - (B @ B).trace() - d * d}
