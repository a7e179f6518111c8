# ruff: noqa
"""Claims whose truth rests on the chart's conventions (A = diag(a), a coordinate read), for `mutate --claims`:
a mutant that drops the coordinate read or the constant matrix changes the chart the exact method takes.
Run: S mutate --claims R/mutate_diag.py --jobs 1 --size 3,2 --report-dir OUT"""
from stiefelsym import admissible, claim, comm


@claim("s71-md-commute", kind="id", sizes=[(3, 2)])
def commute(s):
    """A commutes with the constant diag(1, 2, 3) (A = diag(a))."""
    D = s.mat([[1, 0, 0], [0, 2, 0], [0, 0, 3]], ("n", "n"))
    return {"[A, D]": comm(s.A, D), "AD - DA sym": s.A @ D @ s.X - D @ s.A @ s.X}


@claim("s71-md-read", kind="id", sizes=[(3, 2)])
def read(s):
    """tr(XᵀAX) = Σ aᵢ |row i of X|², written with entries and A₁₂ = 0."""
    lhs = s.tr(s.X.T @ s.A @ s.X)
    rhs = s.A[0, 0] * (s.X[0, 0] * s.X[0, 0] + s.X[0, 1] * s.X[0, 1]) \
        + s.A[1, 1] * (s.X[1, 0] * s.X[1, 0] + s.X[1, 1] * s.X[1, 1]) \
        + s.A[2, 2] * (s.X[2, 0] * s.X[2, 0] + s.X[2, 1] * s.X[2, 1])
    return {"tr": lhs - rhs, "A12": s.A[0, 1] * s.tr(s.P.T @ s.P)}
