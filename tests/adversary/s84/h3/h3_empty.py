"""h3 (stop 84): checks on objects that are empty at some stated size (E_<r at r = 1; the n - r block at r = n).

L = twisted.leading_basis_vectors(s) (r x (r-1)), E = twisted.last_basis_vector(s) (r x 1).  Under the fixed-size
methods a check with no entry at a size is an `error` there (a vacuous check proves nothing).

h3-e-lead-all        {"g": L^T L - I_{r-1}} at 1 <= r <= n <= 3: TRUE at r >= 2, vacuous at r = 1 -> `error` expected.
h3-e-lead-r2         the same, where r > 1: TRUE -> `proved` expected.
h3-e-lead-rin1n      the same, admissible(r_in=(1, "n")): r = 1 stated -> `error` expected.
h3-e-lead-rin2n      the same, admissible(n_min=2, r_in=(2, "n")): no r = 1 -> `proved` expected.
h3-e-lead-rn1        the same, r_is_n=True (n_min=1): (1, 1) stated -> `error` expected.
h3-e-lead-rn2        the same, r_is_n=True, n_min=2: `proved` expected.
h3-e-lead-mixed      {"g": L^T L - I_{r-1}, "t": tr(X^T X) - r}: check g vacuous at r = 1 -> `error` (as fixed sizes).
h3-e-lead-list       {"g": [L^T L - I_{r-1}, tr(X^T X) - r]}: one check, not vacuous at r = 1: TRUE -> `proved`.
h3-e-lead-LLt        {"g": L L^T + E E^T - I_r} (r x r, nonempty at r = 1, where L L^T = 0 and E E^T = 1): TRUE -> `proved`.
h3-e-lead-XL         {"g": (X L)^T (X L) - I_{r-1}} ((r-1) x (r-1)) stated r >= 1 -> `error` expected.
h3-e-lead-PL         {"g": L^T (X^T P + P^T X) L} ((r-1)x(r-1)) stated r > 1: TRUE -> proved.
h3-e-lead-false-r2   {"g": L^T L - 2 I_{r-1}} where r > 1: FALSE -> not proved.
h3-e-nr-zeros        {"z": zeros(n - r, r)} typed ("n-r", "r") at 1 <= r <= n <= 3: empty at r = n -> `error` under
                     every fixed-size method; a free `proved` for all n, r would be the same hollow proof as E_<r's.
h3-e-nr-zeros-lt     the same where r < n: TRUE (0 = 0), proved or undecided.
h3-e-nr-zeros-X      {"z": zeros(n - r, n) @ X}: the same as h3-e-nr-zeros.
h3-e-lead-scaled     {"g": 0 * (L^T X^T A X L)} at 1 <= r <= n: vacuous at r = 1 -> `error` expected.
"""
from stiefelsym import admissible, claim, twisted

SZ = admissible(n_max=3)
SZ2 = admissible(n_max=3, where=lambda n, r: r > 1)
LT = admissible(n_max=3, where=lambda n, r: r < n)


def _g(s):
    L = twisted.leading_basis_vectors(s)
    return L.T @ L - (L.T @ L) @ (L.T @ L)


@claim("h3-e-lead-all", kind="id", sizes=SZ)
def e1(s):
    return {"g": _g(s)}


@claim("h3-e-lead-r2", kind="id", sizes=SZ2)
def e2(s):
    return {"g": _g(s)}


@claim("h3-e-lead-rin1n", kind="id", sizes=admissible(n_max=3, r_in=(1, "n")))
def e3(s):
    return {"g": _g(s)}


@claim("h3-e-lead-rin2n", kind="id", sizes=admissible(n_max=3, n_min=2, r_in=(2, "n")))
def e4(s):
    return {"g": _g(s)}


@claim("h3-e-lead-rn1", kind="id", sizes=admissible(n_max=3, r_is_n=True))
def e5(s):
    return {"g": _g(s)}


@claim("h3-e-lead-rn2", kind="id", sizes=admissible(n_max=3, n_min=2, r_is_n=True))
def e6(s):
    return {"g": _g(s)}


@claim("h3-e-lead-mixed", kind="id", sizes=SZ)
def e7(s):
    return {"g": _g(s), "t": s.tr(s.X.T @ s.X) - s.tr(s.Ir)}


@claim("h3-e-lead-list", kind="id", sizes=SZ)
def e8(s):
    return {"g": [_g(s), s.tr(s.X.T @ s.X) - s.tr(s.Ir)]}


@claim("h3-e-lead-LLt", kind="id", sizes=SZ)
def e9(s):
    L, E = twisted.leading_basis_vectors(s), twisted.last_basis_vector(s)
    return {"g": L @ L.T + E @ E.T - s.Ir}


@claim("h3-e-lead-XL", kind="id", sizes=SZ)
def e10(s):
    L = twisted.leading_basis_vectors(s)
    Y = s.X @ L
    G = L.T @ L
    return {"g": Y.T @ Y - G @ G}


@claim("h3-e-lead-PL", kind="id", sizes=SZ2)
def e11(s):
    L = twisted.leading_basis_vectors(s)
    return {"g": L.T @ (s.X.T @ s.P + s.P.T @ s.X) @ L}


@claim("h3-e-lead-false-r2", kind="id", sizes=SZ2)
def e12(s):
    L = twisted.leading_basis_vectors(s)
    G = L.T @ L
    return {"g": G - G @ G * 2}


@claim("h3-e-nr-zeros", kind="id", sizes=SZ)
def e13(s):
    return {"z": s.zeros(s.n - s.r, s.r, ("n-r", "r"))}


@claim("h3-e-nr-zeros-lt", kind="id", sizes=LT)
def e14(s):
    return {"z": s.zeros(s.n - s.r, s.r, ("n-r", "r"))}


@claim("h3-e-nr-zeros-X", kind="id", sizes=SZ)
def e15(s):
    return {"z": s.zeros(s.n - s.r, s.n, ("n-r", "n")) @ s.X}


@claim("h3-e-lead-scaled", kind="id", sizes=SZ)
def e16(s):
    L = twisted.leading_basis_vectors(s)
    return {"g": 0 * (L.T @ s.X.T @ s.A @ s.X @ L)}
