"""h3 (stop 84): E_<r checks whose r = 1 sizes lie beyond the listed sizes (n_max) but are stated.

L = twisted.leading_basis_vectors(s); G = L^T L; check g = G - G G ((r-1) x (r-1)).
h3-b-lead-where-n4   sizes admissible(n_max=3, where=lambda n, r: r > 1 or n > 3): the listed sizes (n <= 3) all have
                     r >= 2, but the claim is stated for every n (stated_n_max None), so at (4, 1), (5, 1), ... where
                     g is empty (vacuous: `error` at fixed sizes).  A free `proved` "for all n, r" is the hollow proof
                     bb4233a5 removed for listed sizes.
h3-b-lead-where-n4-f the same with check G - 2 G G: FALSE at every r >= 2 (G = I_{r-1}); listed sizes all r >= 2, so not
                     provable anyway (control).
h3-b-lead-stated3    admissible(n_max=3, stated_n_max=3, where=lambda n, r: r > 1): TRUE, no r = 1 -> proved expected.
h3-b-lead-rmin2      admissible(n_max=3, r_min=2): TRUE -> proved expected.
h3-b-lead-nmin4      admissible(n_max=5, n_min=4, where=lambda n, r: r > 1 or n > 4): listed (4,2..4), (5,1..5): r = 1 listed
                     at (5, 1) -> `error` expected (control for the listed case at larger n).
"""
from stiefelsym import admissible, claim, twisted


def _g(s, c=1):
    L = twisted.leading_basis_vectors(s)
    G = L.T @ L
    return G - (G @ G) * c


@claim("h3-b-lead-where-n4", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r > 1 or n > 3))
def b1(s):
    return {"g": _g(s)}


@claim("h3-b-lead-where-n4-f", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r > 1 or n > 3))
def b2(s):
    return {"g": _g(s, 2)}


@claim("h3-b-lead-stated3", kind="id", sizes=admissible(n_max=3, stated_n_max=3, where=lambda n, r: r > 1))
def b3(s):
    return {"g": _g(s)}


@claim("h3-b-lead-rmin2", kind="id", sizes=admissible(n_max=3, r_min=2))
def b4(s):
    return {"g": _g(s)}


@claim("h3-b-lead-nmin4", kind="id", sizes=admissible(n_max=5, n_min=4, where=lambda n, r: r > 1 or n > 4))
def b5(s):
    return {"g": _g(s)}


# (tried: admissible(n_max=3, n_min=4), no listed size: refused when the file loads, "no sizes" -- good)
