"""Batch 4: divisions by numbers that depend on the size, in a residual and inside an Inverse statement.

  b4-div-nr         ((n - r) X) / (n - r) - X = 0                       TRUE where defined (undefined at r = n)
  b4-div-lam-n      ((l - n) X) / (l - n) - X = 0                       TRUE (l generic)
  b4-inv-nr         Inverse of y -> (n - r) y on Sym(r), inverse y/(n - r)   FALSE at r = n (the map is 0 there)
  b4-inv-lam-n      Inverse of y -> (l - n) y, inverse y/(l - n)        TRUE for generic l (l is a parameter)
  b4-inv-2          Inverse of y -> 2y, inverse y/2                     TRUE (control)
"""
from stiefelsym import Inverse, admissible, claim

SZ = admissible(n_max=4)


def _nr(s):
    return s.tr(s.In) - s.tr(s.Ir)


@claim("b4-div-nr", kind="id", sizes=SZ)
def div_nr(s):
    return {"res": (s.X * _nr(s)) / _nr(s) - s.X}


@claim("b4-div-lam-n", kind="id", sizes=SZ)
def div_lam_n(s):
    c = s.lam - s.tr(s.In)
    return {"res": (s.X * c) / c - s.X}


def _inv(c_of):
    def op(t, y):
        return (y * c_of(t),)

    def inv(t, y):
        return (y / c_of(t),)
    return op, inv


@claim("b4-inv-nr", kind="id", sizes=SZ)
def inv_nr(s):
    op, inv = _inv(_nr)
    return {"inverse": Inverse(op, inv, on=("Sym(r)",))}


@claim("b4-inv-lam-n", kind="id", sizes=SZ)
def inv_lam_n(s):
    op, inv = _inv(lambda t: t.lam - t.tr(t.In))
    return {"inverse": Inverse(op, inv, on=("Sym(r)",))}


@claim("b4-inv-2", kind="id", sizes=SZ)
def inv_2(s):
    op, inv = _inv(lambda t: t.q(2))
    return {"inverse": Inverse(op, inv, on=("Sym(r)",))}
