# ruff: noqa
"""Class 2: str constants against sizes (Dim) -- all FALSE statements (a string is not 0).
c2d-n0: (n − n)·'x' ; c2d-n: 'x'·n ; c2d-sum: tr(PᵀP) + ('x'·(n−n)) ; c2d-str-only: '' ; c2d-list: [] ; c2d-none: None
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=3, r_min=2, r_max=2)

@claim("c2d-n0", kind="id", sizes=SZ)
def a(s):
    """FALSE: (n − n)·'x' (a string)."""
    return {"r": (s.n - s.n) * "x"}

@claim("c2d-sum", kind="id", sizes=SZ)
def b(s):
    """FALSE: tr(PᵀP) + ''."""
    return {"r": s.tr(s.P.T @ s.P) + ("x" * 0)}

@claim("c2d-empty", kind="id", sizes=SZ)
def c(s):
    """FALSE-ish: the residual is the empty string ''."""
    return {"r": ""}

@claim("c2d-strlist", kind="id", sizes=SZ)
def d(s):
    """FALSE: the residual is a tuple ('x',)."""
    return {"r": (s.tr(s.P.T @ s.P),)}

@claim("c2d-none", kind="id", sizes=SZ)
def e(s):
    """?: the residual is None."""
    return {"r": None}

@claim("c2d-dimstr", kind="id", sizes=SZ)
def f(s):
    """FALSE: tr(PᵀP)·(n·'x')."""
    return {"r": s.tr(s.P.T @ s.P) * (s.n * "x")}

@claim("c2d-false", kind="id", sizes=SZ)
def g(s):
    """FALSE: False as a residual plus tr PᵀP... residual False."""
    return {"r": False}

@claim("c2d-zero-nonzero", kind="not", expect="nonzero", sizes=SZ)
def h(s):
    """TRUE (a string is not zero?) ... residual '0' stated nonzero."""
    return {"r": "0"}
