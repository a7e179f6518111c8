"""Adversary (generic kinds): a true claim with the symmetric S on R^n and on R^r, whose mutants the free method
may take for true (one letter for both)."""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-mut-spaces", paper="adv", kind="id", sizes=S)
def mut_spaces(s):
    """True: tr(S_n) − tr(S_r) − (tr(S_n) − tr(S_r)) = 0."""
    A, B = s.generic("S", "n", "n", "sym"), s.generic("S", "r", "r", "sym")
    d = A.trace() - B.trace()
    return {"x": A.trace() - B.trace() - d}
