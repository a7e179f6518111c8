"""Adversary (generic kinds): one name, two spaces. The free scene keys gen:NAME:sym without its spaces?"""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-sym-n-vs-r", paper="adv", kind="id", sizes=S)
def sym_n_vs_r(s):
    """False: tr(S_n) = tr(S_r) for two generic symmetric matrices (on R^n and on R^r) of one name."""
    A, B = s.generic("S", "n", "n", "sym"), s.generic("S", "r", "r", "sym")
    return {"tr S_n - tr S_r": A.trace() - B.trace()}


@claim("adv-gk-skew-n-vs-r", paper="adv", kind="id", sizes=S)
def skew_n_vs_r(s):
    """False: tr(K_n K_n) = tr(K_r K_r) for two generic skew matrices (on R^n and on R^r) of one name."""
    A, B = s.generic("K", "n", "n", "skew"), s.generic("K", "r", "r", "skew")
    return {"tr KnKn - tr KrKr": (A @ A).trace() - (B @ B).trace()}


@claim("adv-gk-gen-n-vs-r", paper="adv", kind="id", sizes=S)
def gen_n_vs_r(s):
    """False: tr(G_n) = tr(G_r) (general kind, for comparison)."""
    A, B = s.generic("G", "n", "n"), s.generic("G", "r", "r")
    return {"tr G_n - tr G_r": A.trace() - B.trace()}
