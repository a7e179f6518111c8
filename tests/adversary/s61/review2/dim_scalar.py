"""A size times a positive int (a Dim, a size of blocks) used as a scalar in arithmetic."""
from stiefelsym import admissible, claim

S = admissible(n_max=4, n_min=2)


@claim("ds-true", kind="id", sizes=S)
def ds_true(s):
    """TRUE: 2n X - 2 tr(I_n) X = 0."""
    return {"r": s.X * (s.n * 2) - s.X * (s.tr(s.In) * 2)}


@claim("ds-false-nr", kind="id", sizes=S)
def ds_false_nr(s):
    """FALSE (n != r): 2n X - 2r X = 0."""
    return {"r": s.X * (s.n * 2) - s.X * (s.r * 2)}


@claim("ds-false-k", kind="id", sizes=S)
def ds_false_k(s):
    """FALSE: 3n X - 2 tr(I_n) X = 0."""
    return {"r": s.X * (s.n * 3) - s.X * (s.tr(s.In) * 2)}


@claim("ds-scalar-false", kind="id", sizes=S)
def ds_scalar_false(s):
    """FALSE: 2n - 2r - tr(X^T X) + r = 0 i.e. 2n - 2r = 0 (n != r)."""
    return {"r": s.tr(s.X.T @ s.X) * 0 + (s.n * 2) - (s.r * 2) + s.tr(s.Ir) - s.tr(s.X.T @ s.X)}


@claim("ds-scalar-true", kind="id", sizes=S)
def ds_scalar_true(s):
    """TRUE: tr(I_n)*2 - 2n = 0 as scalars."""
    return {"r": s.tr(s.In) * 2 - (s.n * 2) + s.tr(s.P.T @ s.X) * 0}


@claim("ds-add-false", kind="id", sizes=S)
def ds_add_false(s):
    """FALSE: n*2 + tr(X^T X) - 2 tr(I_n) - r = -? : 2n + r - 2n - r + 1 = 1 != 0."""
    return {"r": (s.n * 2) + s.tr(s.X.T @ s.X) - s.tr(s.In) * 2 - s.tr(s.Ir) + 1}
