"""s89h2 class 2: integer-valued and other Fraction constants in the scene's other constructors (TRUE claims;
an `error` is a false refusal, a `fails` a wrong verdict).
 fm-resolvent-int (TRUE): R(Fraction(2))·(2I − A) = I.
 fm-resolvent-half (TRUE): R(Fraction(1,2))·(½I − A) = I.
 fm-scalar-matrix (TRUE): scalar_matrix(Fraction(3), n) − 3 I_n = 0.
 fm-mat (TRUE, n = 2): s.mat([[Fraction(2), 0], [0, Fraction(2)]], ('n','n')) − 2 I = 0.
 fm-div (TRUE): t / Fraction(2) − t/2 = 0, t = tr PᵀP.
 fm-rsub (TRUE): Fraction(5) − (Fraction(5) − t) − t = 0.
 fm-lam (TRUE): λ·Fraction(4) − 4λ = 0.
 fm-neg-int (TRUE): Fraction(-1)·t + t = 0.
"""
from fractions import Fraction
from stiefelsym import admissible, claim
ANY = admissible(n_max=3)
N2 = [(2, 1), (2, 2)]
def t_(s): return s.tr(s.P.T @ s.P)

@claim("fm-resolvent-int", kind="id", sizes=ANY)
def a(s):
    """TRUE: R(2)(2I − A) = I."""
    return {"r": s.resolvent(Fraction(2)) @ (2 * s.In - s.A) - s.In}

@claim("fm-resolvent-half", kind="id", sizes=ANY)
def b(s):
    """TRUE: R(1/2)(I/2 − A) = I."""
    return {"r": s.resolvent(Fraction(1, 2)) @ (s.In / 2 - s.A) - s.In}

@claim("fm-scalar-matrix", kind="id", sizes=ANY)
def c(s):
    """TRUE: scalar_matrix(3) = 3I."""
    return {"r": s.scalar_matrix(Fraction(3), s.n, "n") - 3 * s.In}

@claim("fm-mat", kind="id", sizes=N2)
def d(s):
    """TRUE: diag(2, 2) = 2I at n = 2."""
    return {"r": s.mat([[Fraction(2), 0], [0, Fraction(2)]], ("n", "n")) - 2 * s.In}

@claim("fm-div", kind="id", sizes=ANY)
def e(s):
    """TRUE: t / Fraction(2) = t / 2."""
    return {"r": t_(s) / Fraction(2) - t_(s) / 2}

@claim("fm-rsub", kind="id", sizes=ANY)
def f(s):
    """TRUE: 5 − (5 − t) − t = 0 with Fraction(5)."""
    return {"r": Fraction(5) - (Fraction(5) - t_(s)) - t_(s)}

@claim("fm-lam", kind="id", sizes=ANY)
def g(s):
    """TRUE: λ·Fraction(4) = 4λ."""
    return {"r": s.lam * Fraction(4) - 4 * s.lam}

@claim("fm-neg-int", kind="id", sizes=ANY)
def h(s):
    """TRUE: Fraction(-1)·t + t = 0."""
    return {"r": Fraction(-1) * t_(s) + t_(s)}
